#pragma once
// Where a run's records go (the stage runner writes through it, stage_runner.hpp): the CLI's
// files (file_sink.hpp), or nothing (a binding that reads the world itself), or a binding's own.
// Across MPI ranks every rank calls every method alike (frames, rows and checkpoints are
// collective: the world's measures are reduced, its state gathered).

#include <string>

#include "sqdem/scene/run_checkpoint.hpp"
#include "sqdem/world/world.hpp"

namespace sqdem {

class RunSink {
 public:
  virtual ~RunSink() = default;
  /// A frame: the state a run starts from, then output.frames per stage and a stage's last.
  virtual void frame(const World& /*world*/) {}
  /// A row of the run's log (every output.log_every steps, and at each stage's end).
  virtual void row(const World& /*world*/, long /*step*/, const std::string& /*stage*/) {}
  /// A state to resume from: at the end of stage `ended`, or (ended empty) the latest, every
  /// output.checkpoint_every_* and when a run is stopped.
  virtual void checkpoint(const World& /*world*/, const RunProgress& /*progress*/, const std::string& /*ended*/) {}
  /// A stage ended (after its last row), with the world as it left it.
  virtual void stageEnded(const World& /*world*/, const StageSpec& /*stage*/) {}
  /// The run completed every stage: its final state.
  virtual void completed(const World& /*world*/) {}
  /// Whether checkpoints are kept at all (a sink without files: the runner skips the clock).
  virtual bool keepsCheckpoints() const { return false; }
};

}  // namespace sqdem
