#pragma once
// A contact whose law waits for its true-gap rungs (docs/architecture.md, "A step"): a group's
// kernel hands it over with what its law then needs; the team solves the step's waiting rungs
// from one shared queue (a rung solve costs ~0.3 ms, hundreds of contact-steps: left in the
// kernel it would land on whichever thread's share holds the contact; each rung a queue entry
// of its own), then each thread enters the solutions and completes the laws it handed over, as
// the kernel would have.

#include <array>
#include <cstdint>

#include "sqdem/interaction/contact_model.hpp"
#include "sqdem/truegap/pair_gap.hpp"
#include "sqdem/truegap/true_gap_rungs.hpp"

namespace sqdem {

struct DeferredLaw {
  std::uint32_t contact = 0;  ///< the store's slot
  std::uint32_t group = 0;    ///< the Interactions group it belongs to
  LawGeometry view;           ///< the law's view of the contact (rungs not yet handed on)
  ContactKinematics motion;
  Vec3 point = Vec3::Zero();  ///< the contact point (m), the record's
  PairGap gap;                ///< the pose the rungs are solved on
  /// The rungs of the overlap's segment, k and k + 1 (TrueGapRungs::segment), solved this step
  /// (none where the ladder held one).
  std::array<RungSolution, 2> solutions;
};

}  // namespace sqdem
