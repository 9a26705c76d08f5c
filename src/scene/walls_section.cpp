// The scene's `walls:` (scene_sections.hpp).

#include <initializer_list>
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

/// A non-zero direction under `key`, made a unit vector.
Vec3 unitVector(const Reader& r, const YAML::Node& wall, const char* key, const std::string& where) {
  const Vec3 v = r.vector(wall, key, where);
  if (!(v.norm() > 0.0)) r.fail(wall[key], where + "." + key, "must be non-zero");
  return v.normalized();
}

/// Fails on each of `keys` the wall gives: they belong to another shape.
void refuseKeys(const Reader& r, const YAML::Node& wall, const std::string& where, std::initializer_list<const char*> keys,
                const std::string& why) {
  for (const char* key : keys) {
    if (wall[key]) r.fail(wall[key], where + "." + key, why);
  }
}

/// `normal`: an infinite plane through the point.
void readPlane(const Reader& r, const YAML::Node& wall, const std::string& where, WallSpec& w, const Vec3& point) {
  w.wall.surface = PlaneWall{Plane{point, unitVector(r, wall, "normal", where)}};
  refuseKeys(r, wall, where, {"radius", "length", "ends", "spin"}, "belongs to a cylinder (axis), not a plane (normal)");
  if (wall["angular_velocity"]) r.fail(wall["angular_velocity"], where + ".angular_velocity", "belongs to a mesh; a plane does not rotate");
}

/// `axis` and `radius`: a cylinder whose axis passes through the point, infinite or of a `length`
/// with flat or rounded `ends`, spinning at `spin` about its axis.
void readCylinder(const Reader& r, const YAML::Node& wall, const std::string& where, WallSpec& w, const Vec3& point) {
  const Vec3 axis = unitVector(r, wall, "axis", where);
  if (wall["angular_velocity"]) {
    r.fail(wall["angular_velocity"], where + ".angular_velocity", "belongs to a mesh; a cylinder turns about its axis by spin (rad/s)");
  }
  Cylinder c{point, axis, r.positive(wall, "radius", where, "m")};
  w.wall.angularVelocity = r.number(wall, "spin", where, 0.0) * c.axis;
  if (wall["length"]) c.halfLength = 0.5 * r.positive(wall, "length", where, "m");
  if (const YAML::Node ends = wall["ends"]) {
    const std::string kind = r.text(wall, "ends", where);
    if (kind != "flat" && kind != "rounded") r.fail(ends, where + ".ends", "must be flat or rounded");
    if (!c.finite()) r.fail(ends, where + ".ends", "belongs to a finite cylinder: give its length (m)");
    c.flatEnds = kind == "flat";
  }
  w.wall.surface = CylinderWall{c};
}

/// `mesh`: an STL file whose origin is placed at the point, turning about it at `angular_velocity`.
void readMesh(const Reader& r, const YAML::Node& wall, const std::string& where, WallSpec& w, const Vec3& point) {
  w.mesh = std::make_shared<const MeshFeatures>(readMeshWall(r, wall, where));
  w.wall.surface = MeshWall{.origin = point};  // MeshWall::mesh is set where the world takes the mesh
  refuseKeys(r, wall, where, {"radius", "length", "ends", "spin"}, "belongs to a cylinder (axis), not a mesh");
  if (wall["angular_velocity"]) w.wall.angularVelocity = r.vector(wall, "angular_velocity", where);
}

}  // namespace

void readWalls(const Reader& r, const YAML::Node& root, Scene& scene) {
  if (const YAML::Node walls = root["walls"]) {
    if (!walls.IsSequence()) r.fail(walls, "walls", "must be a list");
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const std::string where = "walls[" + std::to_string(k) + "]";
      const YAML::Node wall = walls[k];
      r.allowOnly(wall, where, {"point", "normal", "axis", "radius", "length", "ends", "spin", "mesh", "scale", "angular_velocity", "velocity", "material"});
      WallSpec w;
      const Vec3 point = r.vector(wall, "point", where);
      if (int(wall["normal"].IsDefined()) + int(wall["axis"].IsDefined()) + int(wall["mesh"].IsDefined()) != 1) {
        r.fail(wall, where,
               "needs exactly one of normal [nx, ny, nz] (a plane), axis [ux, uy, uz] with radius (m) (a cylinder) or "
               "mesh: file.stl (a triangle mesh)");
      }
      if (!wall["mesh"] && wall["scale"]) r.fail(wall["scale"], where + ".scale", "belongs to a mesh wall (mesh: file.stl)");
      if (wall["mesh"]) readMesh(r, wall, where, w, point);
      else if (wall["normal"]) readPlane(r, wall, where, w, point);
      else readCylinder(r, wall, where, w, point);
      if (wall["velocity"]) w.wall.velocity = r.vector(wall, "velocity", where);
      if (!wall["material"]) r.fail(wall, where + ".material", "missing");
      w.wall.material = r.lookup(wall["material"], where + ".material", scene.materials, "material");
      scene.walls.push_back(w);
    }
  }
}

}  // namespace sqdem::detail
