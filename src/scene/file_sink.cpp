#include "sqdem/scene/file_sink.hpp"

#include "sqdem/io/run_log.hpp"
#include "sqdem/io/vtk_writer.hpp"
#include "sqdem/scene/electrode_analysis.hpp"
#include "sqdem/scene/particle_file.hpp"

namespace sqdem {

FileSink::FileSink(const Scene& scene, const World& world, RunOutput output, int surfaceResolution)
    : scene_(scene), output_(std::move(output)) {
  frames_ = std::make_unique<VtkSeries>(output_.directory, output_.name,
                                        VtkOutputOptions{scene.output.contacts, surfaceResolution, scene.output.vtkCompression});
  log_ = std::make_unique<RunLog>(file(".csv"), world, scene.output.compressionWall);
  if (scene.output.compressionWall) compression_.emplace();
}

FileSink::~FileSink() = default;

std::filesystem::path FileSink::log() const { return log_->path(); }

void FileSink::frame(const World& world) { frames_->writeFrame(world); }

void FileSink::row(const World& world, long step, const std::string& stage) {
  const std::optional<PlateMeasures> plate = log_->row(world, step, stage);
  if (compression_) compression_->add(world.time(), *plate);
}

void FileSink::checkpoint(const World& world, const RunProgress& progress, const std::string& ended) {
  writeRunCheckpoint(ended.empty() ? latestCheckpoint() : file("_after_" + ended + ".checkpoint"), scene_, progress, world);
}

void FileSink::stageEnded(const World& world, const StageSpec& stage) {
  if (!stage.analysis) return;
  const std::filesystem::path directory = file("_" + stage.name + "_analysis"), particles = directory / "particles.csv";
  if (world.communicator().rank() == 0) std::filesystem::create_directories(directory);
  writeParticleFile(particles, world, scene_.materials);  // collective: gathered on rank 0, which writes it
  if (world.communicator().rank() != 0) return;
  try {
    const AnalysedBed bed = analyseParticles(scene_, readParticleFile(particles, scene_.materials), world.walls(), *stage.analysis);
    writeAnalysis(bed, scene_.path, particles.string(), directory);
    const BedAnalysis& a = bed.analysis;
    analyses_.push_back({stage.name, directory / "analysis.json", a.porosity, a.finePores[2].tortuosityFactor,
                         a.conduction[2].conductivity / a.referenceConductivity, ""});
  } catch (const std::exception& e) {
    analyses_.push_back({stage.name, {}, 0.0, 0.0, 0.0, e.what()});
  }
}

void FileSink::completed(const World& world) {
  writeParticleFile(finalParticles(), world, scene_.materials);
  if (!compression_) return;
  presses_ = compression_->presses();
  compaction_ = compression_->compaction();
  if (world.communicator().rank() == 0) compressionPlot_ = compression_->write(output_.directory, output_.name);
}

}  // namespace sqdem
