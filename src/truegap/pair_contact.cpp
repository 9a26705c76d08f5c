#include "sqdem/truegap/pair_contact.hpp"

#include <stdexcept>
#include <string>

#include "sqdem/truegap/gap_region.hpp"

namespace sqdem {

HalfspaceContact gapContact(const PairGap& gap, double approach, double effectiveModulus, int cells, double tolerance) {
  const GapRegion region = gapRegion(gap, approach);
  for (const double margin : {0.04, 0.2, 0.5}) {
    const HalfspaceSolver solver(gapGrid(gap, region, cells, margin), effectiveModulus);
    HalfspaceContact result = solver.atApproach(approach, tolerance);
    if (!result.converged) {
      throw std::runtime_error("the true gap's contact: no convergence in " + std::to_string(result.iterations) + " iterations");
    }
    if (!result.reachesEdge) return result;
  }
  throw std::runtime_error("the true gap's contact: the pressure reaches the grid's edge at a margin of 50 %");
}

HalfspaceContact boundaryElementContact(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach,
                                        double effectiveModulus, int cells) {
  return gapContact(PairGap(A, B, contact), approach, effectiveModulus, cells);
}

}  // namespace sqdem
