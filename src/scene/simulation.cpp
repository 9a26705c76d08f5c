#include "sqdem/scene/simulation.hpp"

#include <algorithm>
#include <functional>

#include "sqdem/distributed/agreed.hpp"
#include "sqdem/io/plain_name.hpp"
#include "sqdem/scene/build_world.hpp"
#include "sqdem/scene/output_directory.hpp"

namespace sqdem {

std::string defaultRunName(const std::string& scenePath) {
  const std::filesystem::path path(scenePath);
  const std::string extension = path.extension().string();
  return extension == ".yaml" || extension == ".yml" || extension == ".json" ? path.stem().string() : path.filename().string();
}

Simulation::Simulation(Scene scene, const RunOptions& options, std::shared_ptr<const Communicator> ranks)
    : scene_(std::move(scene)), world_(buildWorld(scene_)) {
  world_.setCommunicator(ranks);
  plan_ = planRun(scene_, world_);
  const double dt = world_.timeStep();
  if (options.resume) {
    agreed<SceneError>(*ranks, [&] { start_ = readRunCheckpoint(*options.resume, scene_, world_); });
    if (world_.timeStep() != dt) throw SceneError(options.resume->string() + ": the checkpoint's time step differs from the scene's");
  }
  world_.setThreads(options.threads);
  if (options.simd) world_.setSimdPath(*options.simd);
  std::string name = options.name.empty() ? defaultRunName(scene_.path) : options.name;
  // The name goes into every file's name and into the plot scripts.
  if (!isPlainName(name, 100)) {
    throw SceneError((options.name.empty() ? scene_.path + ": the scene's name (its file's name less .yaml, .yml or .json)" : "the run's name '" + name + "'") +
                     " names the output files: it must be 1-100 letters, digits, '_', '.', '-', not starting with '.' or '-'");
  }
  if (options.resume) name += "_from_step" + std::to_string(start_.totalSteps);
  if (options.out) {
    agreed<SceneError>(*ranks, [&] {
      if (ranks->rank() == 0) prepareOutputDirectory(*options.out, name, !options.resume, options.overwrite);
    });
    files_ = std::make_unique<FileSink>(scene_, world_, RunOutput{*options.out, name}, plan_.surfaceResolution);
  }
  runner_ = std::make_unique<StageRunner>(scene_, world_, plan_, start_, files_ ? static_cast<RunSink&>(*files_) : noFiles_);
}

void Simulation::editParticles(const std::function<void(ParticleStore&)>& change) {
  const double before = world_.kineticEnergy();
  change(world_.particles());
  runner_->stateEdited(std::max(0.0, world_.particlesEdited(before)));
}

}  // namespace sqdem
