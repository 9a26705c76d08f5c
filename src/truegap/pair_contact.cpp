#include "sqdem/truegap/pair_contact.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "sqdem/truegap/gap_region.hpp"

namespace sqdem {

namespace {

/// The contact's reach along t1 and t2: each cell's farthest corner (the grid's axes are the
/// region's, turned against t1, t2: gap_region.hpp).
void addReach(GapContact& c, const GapGrid& grid, const GapRegion& region) {
  const Vec2 e1 = region.major, e2 = region.minor();
  const Vec2 half = 0.5 * (grid.hx * e1.cwiseAbs() + grid.hy * e2.cwiseAbs());
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (!(c.pressure[i + static_cast<std::size_t>(grid.nx) * j] > 0.0)) continue;
      const Vec2 far = (grid.x(i) * e1 + grid.y(j) * e2).cwiseAbs() + half;
      c.reach1 = std::max(c.reach1, far.x()), c.reach2 = std::max(c.reach2, far.y());
    }
  }
}

}  // namespace

GapContact gapContact(const PairGap& gap, double approach, double effectiveModulus, int cells, double tolerance) {
  const GapRegion region = gapRegion(gap, approach);
  for (const double margin : {0.04, 0.2, 0.5}) {
    const GapGrid grid = gapGrid(gap, region, cells, margin);
    GapContact result{HalfspaceSolver(grid, effectiveModulus).atApproach(approach, tolerance)};
    if (!result.converged) {
      throw std::runtime_error("the true gap's contact: no convergence in " + std::to_string(result.iterations) + " iterations");
    }
    if (result.reachesEdge) continue;
    addReach(result, grid, region);
    return result;
  }
  throw std::runtime_error("the true gap's contact: the pressure reaches the grid's edge at a margin of 50 %");
}

HalfspaceContact boundaryElementContact(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach,
                                        double effectiveModulus, int cells) {
  return gapContact(PairGap(A, B, contact), approach, effectiveModulus, cells);
}

}  // namespace sqdem
