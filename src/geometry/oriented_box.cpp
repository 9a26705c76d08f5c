#include "sqdem/geometry/oriented_box.hpp"

#include <cmath>

namespace sqdem {

bool boxesOverlap(const OrientedBox& A, const OrientedBox& B, double margin) {
  const Vec3 a = A.halfExtents.array() + margin;
  const Vec3 b = B.halfExtents.array() + margin;
  const Mat3 R = A.axes.transpose() * B.axes;               // B's axes in A's frame
  const Vec3 t = A.axes.transpose() * (B.centre - A.centre);  // B's centre in A's frame
  constexpr double eps = 1e-12;  // keeps near-parallel edge axes from producing false separation
  const Mat3 absR = R.cwiseAbs().array() + eps;

  for (int i = 0; i < 3; ++i) {  // A's face axes
    if (std::abs(t(i)) > a(i) + absR.row(i).dot(b)) return false;
  }
  for (int j = 0; j < 3; ++j) {  // B's face axes
    if (std::abs(t.dot(R.col(j))) > absR.col(j).dot(a) + b(j)) return false;
  }
  for (int i = 0; i < 3; ++i) {  // edge-edge axes A_i x B_j
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = a(i1) * absR(i2, j) + a(i2) * absR(i1, j);
      const double rb = b(j1) * absR(i, j2) + b(j2) * absR(i, j1);
      if (std::abs(t(i2) * R(i1, j) - t(i1) * R(i2, j)) > ra + rb) return false;
    }
  }
  return true;
}

}  // namespace sqdem
