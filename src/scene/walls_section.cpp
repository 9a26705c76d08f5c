// The scene's `walls:` (scene_sections.hpp).

#include <memory>
#include <string>

#include "sqdem/io/stl_mesh.hpp"

#include "scene_sections.hpp"

namespace sqdem::detail {
namespace {

/// A mesh wall's STL file (relative to the scene's directory), read, repaired (io/stl_mesh.hpp) and
/// scaled to m, with its contact features.
MeshFeatures readMeshWall(const Reader& r, const YAML::Node& wall, const std::string& where) {
  const std::filesystem::path file = r.relative(r.text(wall, "mesh", where));
  if (!std::filesystem::is_regular_file(file)) {
    r.fail(wall["mesh"], where + ".mesh", "cannot open '" + file.string() + "' (paths are relative to the scene file)");
  }
  const double scale = wall["scale"] ? r.positive(wall, "scale", where, "m per STL unit") : 1.0;
  try {
    return MeshFeatures(readStlMesh(file, scale).mesh);
  } catch (const MeshError& e) {
    r.fail(wall["mesh"], where + ".mesh", e.what());
  } catch (const std::invalid_argument& e) {
    r.fail(wall["mesh"], where + ".mesh", file.string() + ": " + e.what());
  }
}

}  // namespace

void readWalls(const Reader& r, const YAML::Node& root, Scene& scene) {
  if (const YAML::Node walls = root["walls"]) {
    if (!walls.IsSequence()) r.fail(walls, "walls", "must be a list");
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const std::string where = "walls[" + std::to_string(k) + "]";
      r.allowOnly(walls[k], where, {"point", "normal", "axis", "radius", "length", "ends", "spin", "mesh", "scale", "angular_velocity", "velocity", "material"});
      WallSpec w;
      w.point = r.vector(walls[k], "point", where);
      // A plane has a normal; a cylinder an axis, a radius and optionally a spin; a mesh a file
      // and optionally an angular velocity about its point.
      if (int(walls[k]["normal"].IsDefined()) + int(walls[k]["axis"].IsDefined()) + int(walls[k]["mesh"].IsDefined()) != 1) {
        r.fail(walls[k], where,
               "needs exactly one of normal [nx, ny, nz] (a plane), axis [ux, uy, uz] with radius (m) (a cylinder) or "
               "mesh: file.stl (a triangle mesh)");
      }
      if (walls[k]["mesh"]) {
        w.shape = WallShape::Mesh;
        w.mesh = std::make_shared<const MeshFeatures>(readMeshWall(r, walls[k], where));
      } else if (walls[k]["scale"]) {
        r.fail(walls[k]["scale"], where + ".scale", "belongs to a mesh wall (mesh: file.stl)");
      }
      const char* direction = walls[k]["normal"] ? "normal" : "axis";
      const Vec3 unit = w.mesh ? Vec3::UnitZ() : r.vector(walls[k], direction, where);
      if (!(unit.norm() > 0.0)) r.fail(walls[k][direction], where + "." + direction, "must be non-zero");
      if (w.mesh) {
        for (const char* key : {"radius", "length", "ends", "spin"}) {
          if (walls[k][key]) r.fail(walls[k][key], where + "." + key, "belongs to a cylinder (axis), not a mesh");
        }
        if (walls[k]["angular_velocity"]) w.angularVelocity = r.vector(walls[k], "angular_velocity", where);
      } else if (walls[k]["normal"]) {
        w.normal = unit.normalized();
        for (const char* key : {"radius", "length", "ends", "spin"}) {
          if (walls[k][key]) r.fail(walls[k][key], where + "." + key, "belongs to a cylinder (axis), not a plane (normal)");
        }
        if (walls[k]["angular_velocity"]) r.fail(walls[k]["angular_velocity"], where + ".angular_velocity", "belongs to a mesh; a plane does not rotate");
      } else {
        if (walls[k]["angular_velocity"]) {
          r.fail(walls[k]["angular_velocity"], where + ".angular_velocity", "belongs to a mesh; a cylinder turns about its axis by spin (rad/s)");
        }
        w.shape = WallShape::Cylinder;
        w.axis = unit.normalized();
        w.radius = r.positive(walls[k], "radius", where, "m");
        w.angularVelocity = r.number(walls[k], "spin", where, 0.0) * w.axis;
        if (walls[k]["length"]) w.length = r.positive(walls[k], "length", where, "m");
        if (const YAML::Node ends = walls[k]["ends"]) {
          const std::string kind = r.text(walls[k], "ends", where);
          if (kind != "flat" && kind != "rounded") r.fail(ends, where + ".ends", "must be flat or rounded");
          if (w.length == 0.0) r.fail(ends, where + ".ends", "belongs to a finite cylinder: give its length (m)");
          w.flatEnds = kind == "flat";
        }
      }
      if (walls[k]["velocity"]) w.velocity = r.vector(walls[k], "velocity", where);
      if (!walls[k]["material"]) r.fail(walls[k], where + ".material", "missing");
      w.material = r.lookup(walls[k]["material"], where + ".material", scene.materials, "material");
      scene.walls.push_back(w);
    }
  }
}

}  // namespace sqdem::detail
