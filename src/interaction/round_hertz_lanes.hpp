#pragma once
// HertzLaw on round contacts, several per instruction (simd_path.hpp; docs/performance.md,
// "SIMD across contacts"): what contact_kernels.cpp's group kernel computes for them, to the bit.

#include <span>

#include "sqdem/interaction/interactions.hpp"
#include "sqdem/interaction/simd_path.hpp"

namespace sqdem::detail {

/// The contacts `members` of a HertzLaw group of a round kind (SphereSphere or SphereWall, whose
/// walls are planes) whose model is `model` as round kinds run it (no curvatures, the circle's
/// Mindlin spring), on `path` (not Scalar, one this CPU runs): detection, the law and every
/// record the group kernel writes, and the step's statistics. Not for a store that keeps
/// energies (the ledger's scenes run contact by contact).
void roundHertzContacts(SimdPath path, PairKind kind, std::span<const std::uint32_t> members, const ContactModel& model,
                        const InteractionScene& scene, ContactStore& s, ContactStatistics& statistics);

}  // namespace sqdem::detail
