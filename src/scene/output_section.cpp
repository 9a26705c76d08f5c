// The scene's `output:` (scene_sections.hpp).

#include <string>

#include "scene_sections.hpp"

namespace sqdem::detail {

void readOutput(const Reader& r, const YAML::Node& root, Scene& scene) {
  if (const YAML::Node out = root["output"]) {
    r.allowOnly(out, "output",
                {"frames", "log_every", "contacts", "surface_resolution", "checkpoint_every_steps", "checkpoint_every_minutes", "energy", "compression",
                 "sphere_orientation", "vtk_compression"});
    scene.output.frames = static_cast<std::size_t>(r.integer(out, "frames", "output", 0.0, 1e5, 20.0));
    scene.output.logEvery = static_cast<std::size_t>(r.integer(out, "log_every", "output", 0.0, 1e12, 0.0));
    scene.output.contacts = r.flag(out, "contacts", "output", true);
    if (out["surface_resolution"]) {
      scene.output.surfaceResolution = static_cast<int>(r.integer(out, "surface_resolution", "output", 0.0, 64.0, 8.0));
    }
    scene.output.checkpointSteps = static_cast<std::uint64_t>(r.integer(out, "checkpoint_every_steps", "output", 0.0, 1e12, 0.0));
    scene.output.checkpointMinutes = r.number(out, "checkpoint_every_minutes", "output", scene.output.checkpointMinutes);
    if (!(scene.output.checkpointMinutes >= 0.0)) {
      r.fail(out["checkpoint_every_minutes"], "output.checkpoint_every_minutes", "must be >= 0 (wall-clock minutes, 0: off)");
    }
    if (const YAML::Node press = out["compression"]) {
      r.allowOnly(press, "output.compression", {"wall"});
      scene.output.compressionWall = r.plate(press, "output.compression", scene.walls);
    }
    scene.output.energy = r.flag(out, "energy", "output", false);
    scene.output.sphereOrientation = r.flag(out, "sphere_orientation", "output", false);
    scene.output.vtkCompression = r.choice(out, "vtk_compression", "output",
                                           {{"zlib", VtkCompression::ZLib}, {"lz4", VtkCompression::LZ4}, {"none", VtkCompression::None}},
                                           VtkCompression::ZLib);
    for (std::size_t k = 0; scene.output.energy && k < scene.interactions.size(); ++k) {
      if (!storesEnergy(scene.interactions[k].normal)) {
        r.fail(out["energy"], "output.energy",
               "the energy ledger needs every interaction's normal law to state its stored elastic energy (" +
                   lawNames([](const NormalLawEntry& e) { return e.traits.storesEnergy; }) +
                   ", without surface_energy); interactions[" +
                   std::to_string(k) + "] uses " + scene.interactions[k].normalName);
      }
    }
  }
}

}  // namespace sqdem::detail
