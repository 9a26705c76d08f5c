#pragma once
// Domain decomposition by recursive coordinate bisection (docs/architecture.md, "Ghosts"; Berger
// & Bokhari, IEEE Trans. Computers 36, 570-580, 1987): the box is cut across its longest edge at
// the coordinate that leaves each side the share of the measured cost of the ranks it gets (a
// box of r ranks: floor(r/2) below, the rest above), and each side again, until every rank has a
// box. Cuts follow the load wherever it sits — a settling bed has every particle at the bottom,
// where a uniform grid would leave the upper ranks idle — and the boxes stay boxes, so that a
// rank's ghosts are the particles near its six faces.
//
// The cut coordinate is found by bisection, every trial one reduction of the cost below it in
// every box being cut (all boxes of a level at once): the points may be spread over the ranks.
// The result depends only on the points and their costs, not on how they are spread.

#include <span>
#include <vector>

#include "sqdem/distributed/communicator.hpp"
#include "sqdem/geometry/domain.hpp"

namespace sqdem {

/// A rank's part of the domain: it owns the centres x with lo <= x < hi along every direction.
/// Along a direction that is not periodic the outer faces lie at -inf / +inf (particles may leave
/// the box there).
struct SubDomain {
  Vec3 lo, hi;
  bool owns(const Vec3& x) const { return (x.array() >= lo.array()).all() && (x.array() < hi.array()).all(); }
};

/// The whole box as one process's sub-domain (its open faces at -inf / +inf).
SubDomain wholeBox(const Domain& box);

/// The sub-domains of `ranks` ranks (index = rank): this process's points (centres, wrapped into
/// the box) with their costs (> 0), reduced over `ranks`' communicator. The cut leaves each side
/// its share of the cost to within the largest single cost.
std::vector<SubDomain> bisect(const Domain& box, std::span<const Vec3> points, std::span<const double> costs, int ranks,
                              const Communicator& communicator);

/// The rank whose sub-domain owns x.
int ownerOf(const std::vector<SubDomain>& parts, const Vec3& x);

}  // namespace sqdem
