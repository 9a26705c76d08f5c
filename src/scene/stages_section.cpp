// The scene's `stages:` (scene_sections.hpp).

#include <algorithm>
#include <string>

#include "sqdem/io/plain_name.hpp"

#include "scene_sections.hpp"

namespace sqdem::detail {

void readStages(const Reader& r, const YAML::Node& root, Scene& scene) {
  const YAML::Node stages = root["stages"];
  if (!stages || !stages.IsSequence() || stages.size() == 0) r.fail(stages ? stages : root, "stages", "missing (a list of {name, duration, stop})");
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const std::string where = "stages[" + std::to_string(k) + "]";
    const YAML::Node st = stages[k];
    r.allowOnly(st, where, {"name", "duration", "stop", "move_wall", "servo_wall", "viscous_damping", "form_bonds", "analyse"});
    StageSpec spec;
    spec.name = st["name"] ? r.text(st, "name", where) : "stage" + std::to_string(k);
    // Stage names go into CSV rows and file names.
    if (!isPlainName(spec.name, 64)) {
      r.fail(st["name"], where + ".name", "must be 1-64 letters, digits, '_', '.', '-', not starting with '.' or '-'");
    }
    for (const StageSpec& other : scene.stages) {
      if (other.name == spec.name) r.fail(st["name"], where + ".name", "'" + spec.name + "' names an earlier stage too");
    }
    spec.duration = r.positive(st, "duration", where, "s");
    spec.viscousDamping = r.number(st, "viscous_damping", where, 0.0);
    if (spec.viscousDamping < 0.0) r.fail(st["viscous_damping"], where + ".viscous_damping", "must be >= 0 (1/s)");
    if (const YAML::Node bonds = st["form_bonds"]) {
      r.allowOnly(bonds, where + ".form_bonds", {"gap"});
      spec.bondGap = r.number(bonds, "gap", where + ".form_bonds");
      if (!(*spec.bondGap >= 0.0)) r.fail(bonds["gap"], where + ".form_bonds.gap", "must be >= 0 (the largest gap over the smaller volume radius)");
      if (std::none_of(scene.interactions.begin(), scene.interactions.end(), [](const InteractionSpec& i) { return i.bond.has_value(); })) {
        r.fail(bonds, where + ".form_bonds", "no interaction has a bond: give one a 'bond' {normal_stiffness, ...}");
      }
    }
    if (const YAML::Node analyse = st["analyse"]) {
      // `analyse: true`, or {voxels, region: [z_low, z_high]}.
      const std::string at = where + ".analyse";
      if (analyse.IsMap()) {
        r.allowOnly(analyse, at, {"voxels", "region"});
        AnalysisSpec& a = spec.analysis.emplace();
        a.voxels = static_cast<int>(r.integer(analyse, "voxels", at, 4, 256, 64));
        if (const YAML::Node region = analyse["region"]) {
          if (!region.IsSequence() || region.size() != 2) r.fail(region, at + ".region", "must be [z_low, z_high] (m)");
          a.zLow = r.asNumber(region[0], at + ".region");
          a.zHigh = r.asNumber(region[1], at + ".region");
          if (!(*a.zHigh > *a.zLow)) r.fail(region, at + ".region", "needs z_low < z_high (m)");
        }
      } else {
        bool on = false;
        if (!YAML::convert<bool>::decode(analyse, on)) r.fail(analyse, at, "must be true, false or {voxels, region: [z_low, z_high]}");
        if (on) spec.analysis.emplace();
      }
    }
    if (const YAML::Node stop = st["stop"]) {
      r.allowOnly(stop, where + ".stop", {"kinetic_energy_ratio", "velocity_scale", "wall_pressure", "porosity", "wall", "after"});
      if (!stop["kinetic_energy_ratio"] && !stop["wall_pressure"] && !stop["porosity"]) {
        r.fail(stop, where + ".stop", "needs kinetic_energy_ratio, wall_pressure or porosity (the last two with wall)");
      }
      if (stop["kinetic_energy_ratio"]) {
        spec.kineticEnergyRatio = r.positive(stop, "kinetic_energy_ratio", where + ".stop", "-");
        if (stop["velocity_scale"]) {
          spec.velocityScale = r.positive(stop, "velocity_scale", where + ".stop", "m/s");
        } else if (scene.gravity.norm() == 0.0) {
          r.fail(stop, where + ".stop.kinetic_energy_ratio",
                 "without gravity needs velocity_scale (m/s): the ratio is then E_kin / sum m v_s^2 / 2");
        }
      } else if (stop["velocity_scale"]) {
        r.fail(stop["velocity_scale"], where + ".stop.velocity_scale", "belongs to kinetic_energy_ratio");
      }
      if (stop["wall_pressure"]) {
        spec.wallPressure = r.positive(stop, "wall_pressure", where + ".stop", "Pa");
        spec.pressureWall = r.plane(stop, where + ".stop", scene.walls);
      }
      if (stop["porosity"]) {
        spec.porosity = r.number(stop, "porosity", where + ".stop");
        if (!(spec.porosity > 0.0 && spec.porosity < 1.0)) r.fail(stop["porosity"], where + ".stop.porosity", "must be in (0, 1)");
        spec.pressureWall = r.plate(stop, where + ".stop", scene.walls);
      }
      spec.minimumDuration = r.number(stop, "after", where + ".stop", 0.0);
    }
    if (const YAML::Node move = st["move_wall"]) {
      const std::string at = where + ".move_wall";
      r.allowOnly(move, at, {"wall", "velocity", "path"});
      spec.wall = r.wallIndex(move, at, scene.walls.size());
      if (move["velocity"].IsDefined() == move["path"].IsDefined()) {
        r.fail(move, at, "needs exactly one of velocity [vx, vy, vz] (m/s) or path [[t (s), offset (m)], ...]");
      }
      if (move["velocity"]) spec.wallVelocity = r.vector(move, "velocity", at);
      if (const YAML::Node path = move["path"]) {
        const std::string key = at + ".path";
        r.plane(move, at, scene.walls);  // the path runs along the plane's normal
        if (!path.IsSequence() || path.size() == 0) r.fail(path, key, "must be a list of [t (s), offset along the wall normal (m)] points");
        double last = 0.0;
        for (const auto& point : path) {
          if (!point.IsSequence() || point.size() != 2) r.fail(point, key, "each point is [t (s), offset (m)]");
          const double t = r.asNumber(point[0], key), x = r.asNumber(point[1], key);
          if (!(t > last)) r.fail(point, key, "times must be > 0 and increasing (s)");
          last = t;
          spec.wallPath.points.push_back({t, x});
        }
      }
    }
    if (const YAML::Node servo = st["servo_wall"]) {
      r.allowOnly(servo, where + ".servo_wall", {"wall", "pressure", "max_speed"});
      spec.servoWall = r.plane(servo, where + ".servo_wall", scene.walls);
      if (spec.wall == spec.servoWall) r.fail(servo, where + ".servo_wall", "the same wall cannot also be in move_wall");
      spec.servo.pressure = r.positive(servo, "pressure", where + ".servo_wall", "Pa");
      spec.servo.maxSpeed = r.positive(servo, "max_speed", where + ".servo_wall", "m/s");
    }
    scene.stages.push_back(spec);
  }
}

}  // namespace sqdem::detail
