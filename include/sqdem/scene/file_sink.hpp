#pragma once
// A run's files (the CLI's sink, run_sink.hpp) in its output directory, each named
// `<name>_...`: the VTK frames (io/vtk_writer.hpp), the CSV log (io/run_log.hpp), the checkpoints
// `<name>_after_<stage>.checkpoint` and `<name>_latest.checkpoint` (run_checkpoint.hpp), the
// particle file of the final state `<name>_final_particles.csv` (particle_file.hpp) and, for a
// scene with a pressing plate, `<name>_compression.csv/.png` (compression_report.hpp). Across
// ranks rank 0 writes every file but the frames' pieces.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "sqdem/scene/compression_report.hpp"
#include "sqdem/scene/run_sink.hpp"
#include "sqdem/scene/scene.hpp"

namespace sqdem {

class RunLog;
class VtkSeries;

struct RunOutput {
  std::filesystem::path directory;
  std::string name;  ///< prefix of every file of the run
};

class FileSink final : public RunSink {
 public:
  /// Creates the log (throws std::runtime_error if it cannot); `surfaceResolution` as planned
  /// (RunPlan). The directory is prepared beforehand (output_directory.hpp).
  FileSink(const Scene& scene, const World& world, RunOutput output, int surfaceResolution);
  ~FileSink() override;

  void frame(const World& world) override;
  void row(const World& world, long step, const std::string& stage) override;
  void checkpoint(const World& world, const RunProgress& progress, const std::string& ended) override;
  /// A stage with `analyse`: its particles written (<name>_<stage>_analysis/particles.csv) and
  /// analysed on rank 0 with the walls where they are, into that directory (electrode_analysis.hpp).
  void stageEnded(const World& world, const StageSpec& stage) override;
  void completed(const World& world) override;
  bool keepsCheckpoints() const override { return true; }

  const RunOutput& output() const { return output_; }
  std::filesystem::path log() const;
  std::filesystem::path latestCheckpoint() const { return file("_latest.checkpoint"); }
  /// The particle file of the final state (after completed()).
  std::filesystem::path finalParticles() const { return file("_final_particles.csv"); }
  /// With a pressing plate, after completed(): what the press did (of this run's rows: a resumed
  /// run's from its checkpoint on) and its plot, when gnuplot made one.
  const std::vector<CompressionSummary>& presses() const { return presses_; }
  const std::optional<CompactionFit>& compaction() const { return compaction_; }
  const std::optional<std::filesystem::path>& compressionPlot() const { return compressionPlot_; }
  /// The stages' analyses so far (rank 0): where, and their headline numbers, or why it failed
  /// (a failed analysis does not stop the run).
  struct AnalysisSummary {
    std::string stage;
    std::filesystem::path json;
    double porosity = 0.0, tortuosityZ = 0.0, conductivityRatioZ = 0.0;
    std::string error;
  };
  const std::vector<AnalysisSummary>& analyses() const { return analyses_; }

 private:
  std::filesystem::path file(const std::string& suffix) const { return output_.directory / (output_.name + suffix); }

  const Scene& scene_;
  RunOutput output_;
  std::unique_ptr<VtkSeries> frames_;
  std::unique_ptr<RunLog> log_;
  std::optional<CompressionRecord> compression_;
  std::vector<CompressionSummary> presses_;
  std::optional<CompactionFit> compaction_;
  std::optional<std::filesystem::path> compressionPlot_;
  std::vector<AnalysisSummary> analyses_;
};

}  // namespace sqdem
