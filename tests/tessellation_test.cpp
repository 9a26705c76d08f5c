// A superquadric's drawn surface (geometry/superquadric_tessellation.hpp): every vertex on the
// surface (g = 1), a closed and consistently oriented quad mesh, and the volume
// it encloses (sum of signed tetrahedra from the centre) within 1 % of the closed form
// (Jaklic et al. 2000, Superquadric::volume) from N = 12 on (the output's default N = 8 falls
// 1.7 % short on a sphere, less on blocks: drawing, not measuring), for spheres,
// ellipsoids, blocks and mixed exponents up to n = 20.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "sqdem/geometry/superquadric_tessellation.hpp"

namespace sqdem {
namespace {

/// The resolution from which the drawn volume is within 1 %.
constexpr int resolution = 12;

double enclosedVolume(const Tessellation& t) {
  double sixTimes = 0.0;
  for (const auto& q : t.quads) {
    for (const auto& [i, j, k] : {std::array{q[0], q[1], q[2]}, std::array{q[0], q[2], q[3]}}) {
      sixTimes += t.points[i].dot(t.points[j].cross(t.points[k]));
    }
  }
  return sixTimes / 6.0;
}

TEST(Tessellation, ClosedOnTheSurfaceAndEnclosingTheVolume) {
  for (const Superquadric& s : {Superquadric::sphere(1.3), Superquadric::ellipsoid(1.0, 0.5, 0.3), Superquadric(1.0, 0.8, 0.6, 6.0, 6.0),
                                Superquadric(1.0, 0.6, 0.9, 2.0, 6.0), Superquadric(1.0, 0.6, 0.9, 6.0, 2.0),
                                Superquadric(1.0, 0.6, 0.9, 20.0, 20.0)}) {
    SCOPED_TRACE(testing::Message() << "n1 " << s.n1() << ", n2 " << s.n2() << ", semi-axes " << s.halfExtents().transpose());
    const Tessellation t = tessellate(s, resolution);
    const int N = resolution;
    ASSERT_EQ(t.quads.size(), 6u * N * N);
    ASSERT_EQ(t.points.size(), 6u * N * N + 2);
    for (std::size_t i = 0; i < t.points.size(); ++i) {
      EXPECT_NEAR(s.implicitFunction(t.points[i]), 0.0, 1e-12);
    }
    // Closed and consistently oriented: every directed edge once, and its reverse once.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& q : t.quads) {
      for (int c = 0; c < 4; ++c) ++edges[{q[c], q[(c + 1) % 4]}];
      // Counter-clockwise seen from outside: the quad's normal points away from the centre.
      const Vec3 normal = (t.points[q[2]] - t.points[q[0]]).cross(t.points[q[3]] - t.points[q[1]]);
      EXPECT_GT(normal.dot(t.points[q[0]] + t.points[q[2]]), 0.0);
    }
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
    }
    const double error = enclosedVolume(t) / s.volume() - 1.0;
    std::printf("n1 %4.1f n2 %4.1f: resolution %d encloses %+.3f %% of the volume\n", s.n1(), s.n2(), N, 100.0 * error);
    EXPECT_LT(error, 0.0);  // vertices on a convex surface: the polyhedron lies inside
    EXPECT_GT(error, -0.01);
  }
}

TEST(Tessellation, ConvergesAtSecondOrder) {
  // An inscribed polyhedron's volume deficit shrinks as 1 / N^2.
  const Superquadric s(1.0, 0.8, 0.6, 6.0, 6.0);
  std::vector<double> errors;
  for (const int N : {4, 8, 16, 32}) errors.push_back(std::abs(enclosedVolume(tessellate(s, N)) / s.volume() - 1.0));
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_NEAR(errors[k - 1] / errors[k], 4.0, 0.6) << "step " << k;
  EXPECT_THROW(tessellate(s, 0), std::invalid_argument);
}

}  // namespace
}  // namespace sqdem
