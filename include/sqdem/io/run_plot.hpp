#pragma once
// A run's plot (`sqdem plot`, and written at the end of `sqdem run`): from the CSV log
// (run_log.hpp), <name>_run.png through gnuplot (gnuplot.hpp; the script <name>_run.gp next to
// it): kinetic energy (log scale), solid fraction (the bed's and between the walls), mean
// coordination and the plane walls' pressures against time, and for a compression scene the
// plate pressure against the solid fraction between the plates.

#include <filesystem>
#include <optional>

namespace sqdem {

/// Plots the log `csv` (an sqdem run log: its header starts time_s,step,stage). Returns the PNG,
/// or nothing when gnuplot is not installed; throws std::runtime_error naming the file when it
/// is not a run log or its name is not a plain file name (letters, digits, _ . -).
std::optional<std::filesystem::path> plotRun(const std::filesystem::path& csv);

}  // namespace sqdem
