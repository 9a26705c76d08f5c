// STL meshes (io/stl_mesh.hpp): ASCII and binary files of a unit cube and of a square, written
// here with the flaws exporters leave (every vertex repeated per triangle, a flipped triangle, a
// degenerate one), read back repaired. Closed forms: the cube's area 6 and volume 1 (outward
// normals give a positive divergence-theorem volume), the square's area 1.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "sqdem/io/stl_mesh.hpp"

namespace sqdem {
namespace {

using Triangle = std::array<Vec3, 3>;

/// The unit cube [0, 1]^3 as 12 outward triangles.
std::vector<Triangle> cube() {
  const auto v = [](int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
  // Faces as corner indices, counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Triangle> t;
  for (const auto& q : quads) {
    t.push_back({v(q[0]), v(q[1]), v(q[2])});
    t.push_back({v(q[0]), v(q[2]), v(q[3])});
  }
  return t;
}

std::filesystem::path scratch(const std::string& name) { return std::filesystem::temp_directory_path() / ("sqdem_test_" + name); }

void writeAscii(const std::filesystem::path& path, const std::vector<Triangle>& triangles) {
  std::ofstream out(path);
  out << "solid test\n";
  for (const Triangle& t : triangles) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (const Vec3& p : t) out << "      vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << "\n";
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid test\n";
}

void writeBinary(const std::filesystem::path& path, const std::vector<Triangle>& triangles) {
  std::ofstream out(path, std::ios::binary);
  const char header[80] = "binary STL written by sqdem's test";
  out.write(header, 80);
  const auto count = static_cast<std::uint32_t>(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const Triangle& t : triangles) {
    float record[12] = {};
    for (int c = 0; c < 3; ++c) {
      for (int d = 0; d < 3; ++d) record[3 + 3 * c + d] = static_cast<float>(t[c](d));
    }
    out.write(reinterpret_cast<const char*>(record), sizeof record);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

// A cube whose exporter flipped one triangle and added a degenerate one: the repaired mesh has
// 8 vertices and 12 outward triangles; read as ASCII and as binary, and scaled.
TEST(StlMesh, CubeIsRepairedAndOrientedOutwards) {
  std::vector<Triangle> flawed = cube();
  std::swap(flawed[3][1], flawed[3][2]);                          // flipped
  flawed.push_back({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0)});  // zero area
  writeAscii(scratch("cube_ascii.stl"), flawed);
  writeBinary(scratch("cube_binary.stl"), flawed);
  for (const char* name : {"cube_ascii.stl", "cube_binary.stl"}) {
    const StlMesh read = readStlMesh(scratch(name), 2e-3);  // the file in mm, the scene in m
    const TriangleMesh& m = read.mesh;
    SCOPED_TRACE(name);
    EXPECT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(read.repairs.trianglesRead, 13u);
    EXPECT_EQ(read.repairs.trianglesRemoved, 1u);
    EXPECT_EQ(read.repairs.verticesMerged, 39u - 8u);
    EXPECT_TRUE(read.repairs.closed);
    EXPECT_TRUE(m.closed());
    EXPECT_NEAR(m.area(), 6.0 * 4e-6, 1e-18);
    EXPECT_NEAR(m.volume(), 8e-9, 1e-21);  // > 0: outwards
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {  // each normal points away from the centre
      const Vec3 centroid = (m.vertices[m.triangles[t][0]] + m.vertices[m.triangles[t][1]] + m.vertices[m.triangles[t][2]]) / 3.0;
      EXPECT_GT(m.normal(t).dot(centroid - Vec3::Constant(1e-3)), 0.0) << "triangle " << t;
    }
  }
}

// A cube listed inside out (every triangle flipped) comes back outwards.
TEST(StlMesh, InsideOutCubeIsTurned) {
  std::vector<Triangle> inside = cube();
  for (Triangle& t : inside) std::swap(t[1], t[2]);
  writeAscii(scratch("cube_inside_out.stl"), inside);
  const StlMesh read = readStlMesh(scratch("cube_inside_out.stl"));
  EXPECT_TRUE(read.repairs.closed);
  EXPECT_NEAR(read.mesh.volume(), 1.0, 1e-15);
}

// An open sheet (a square of two triangles, one flipped) is made consistent but stays open.
TEST(StlMesh, OpenSquareIsMadeConsistent) {
  writeBinary(scratch("square.stl"), {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, {Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}});
  const StlMesh read = readStlMesh(scratch("square.stl"));
  const TriangleMesh& m = read.mesh;
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_FALSE(read.repairs.closed);
  EXPECT_FALSE(m.closed());
  EXPECT_TRUE(read.repairs.reoriented);
  EXPECT_NEAR(m.area(), 1.0, 1e-15);
  EXPECT_NEAR(std::abs(m.normal(0).z()), 1.0, 1e-15);
  EXPECT_EQ(m.normal(0), m.normal(1));
}

// Files that are not meshes: a clear message naming the file.
TEST(StlMesh, BadFilesAreRefusedByName) {
  std::ofstream(scratch("empty.stl")) << "";
  std::ofstream(scratch("text.stl")) << "this is not an STL file\n";
  for (const char* name : {"empty.stl", "text.stl", "missing.stl"}) {
    try {
      readStlMesh(scratch(name));
      ADD_FAILURE() << name << " was accepted";
    } catch (const MeshError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sqdem
