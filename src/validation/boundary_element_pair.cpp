#include "sqdem/validation/boundary_element_pair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sqdem/contact/surface_along_line.hpp"
#include "sqdem/mechanics/elliptic.hpp"

namespace sqdem {
namespace {

/// The tangent plane of the contact and the gap above its points.
struct TangentPlane {
  Vec3 origin, normal, t1, t2;
  double overlap;

  TangentPlane(const ContactGeometry& c)
      : origin(0.5 * (c.pointA + c.pointB)),
        normal(c.normal),
        t1(contactMajorAxis(c.curvatureA, c.curvatureB, c.normal)),
        t2(c.normal.cross(t1)),
        overlap(c.overlap) {}

  double gap(const PairBody& A, const PairBody& B, double x, double y) const {
    const Vec3 q = origin + x * t1 + y * t2;
    const double top = surfaceFarthestAlong(A.shape, A.pose, q, normal), bottom = -surfaceFarthestAlong(B.shape, B.pose, q, -normal);
    return bottom - top + overlap;  // +infinity where a line misses a body
  }
};

}  // namespace

GapGrid touchingGap(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach, int cells) {
  if (!contact.converged()) throw std::invalid_argument("touchingGap: the detector's contact did not converge");
  if (!(approach > 0.0) || cells < 2) throw std::invalid_argument("touchingGap: the approach must be > 0 and cells >= 2");
  const TangentPlane plane(contact);
  // The region h < delta is convex (each body's height over the plane is concave): its bounding
  // box from a coarse scan of 33 x 33 points (one on the contact point) over a square widened
  // until the region lies inside it and narrowed while it fills less than a quarter of it.
  const int scan = 33;
  double width = std::sqrt(2.0 * referenceVolumeRadius(A.shape, B.shape) * approach);
  std::array<double, 4> box{};  // x low, x high, y low, y high
  bool bracketed = false;
  for (int attempt = 0; attempt < 60 && !bracketed; ++attempt) {
    const double step = 2.0 * width / (scan - 1);
    box = {width, -width, width, -width};
    for (int j = 0; j < scan; ++j) {
      for (int i = 0; i < scan; ++i) {
        const double x = -width + i * step, y = -width + j * step;
        if (plane.gap(A, B, x, y) >= approach) continue;
        box = {std::min(box[0], x), std::max(box[1], x), std::min(box[2], y), std::max(box[3], y)};
      }
    }
    if (box[0] > box[1]) {
      throw std::runtime_error("touchingGap: no point of the tangent plane where the gap is below the approach " +
                               std::to_string(approach) + " m (the detector's overlap " + std::to_string(contact.overlap) + " m)");
    }
    const double extent = std::max({-box[0], box[1], -box[2], box[3]});
    if (extent >= width - 0.5 * step) width *= 2.0;
    else if (extent < 0.25 * width) width *= 0.5;
    else {
      box = {box[0] - step, box[1] + step, box[2] - step, box[3] + step};
      bracketed = true;
    }
  }
  if (!bracketed) throw std::runtime_error("touchingGap: the region where the gap is below the approach is not bounded in 60 scans");
  GapGrid grid;
  grid.nx = grid.ny = cells;
  grid.x0 = box[0];
  grid.y0 = box[2];
  grid.hx = (box[1] - box[0]) / cells;
  grid.hy = (box[3] - box[2]) / cells;
  grid.gap.resize(static_cast<std::size_t>(cells) * cells);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) grid.gap[i + static_cast<std::size_t>(cells) * j] = plane.gap(A, B, grid.x(i), grid.y(j));
  }
  return grid;
}

HalfspaceContact boundaryElementContact(const PairBody& A, const PairBody& B, const ContactGeometry& contact, double approach,
                                        double effectiveModulus, int cells) {
  const HalfspaceSolver solver(touchingGap(A, B, contact, approach, cells), effectiveModulus);
  HalfspaceContact result = solver.atApproach(approach);
  if (!result.converged) {
    throw std::runtime_error("boundaryElementContact: no convergence in " + std::to_string(result.iterations) + " iterations");
  }
  if (result.reachesEdge) throw std::runtime_error("boundaryElementContact: the pressure reaches the grid's edge");
  return result;
}

}  // namespace sqdem
