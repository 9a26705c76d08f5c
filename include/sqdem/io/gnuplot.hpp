#pragma once
// PNG plots through gnuplot (Debian's gnuplot-nox, installed by scripts/setup.sh): the script is
// written next to the data so a user can restyle and rerun it; gnuplot runs without a shell
// (posix_spawn: no user text is ever parsed as a command), writes the PNG under a temporary
// name, and the PNG is renamed into place only when gnuplot succeeded.
//
// A script must open with the lines `preamble(name)` returns: they set the terminal and take the
// output file from the variable `output` (set by plotPng), else <name>.png when the user reruns
// `gnuplot <name>.gp` in the directory.

#include <filesystem>
#include <optional>
#include <string>

namespace sqdem {

/// The first lines of a script whose plot is `<name>.png`.
std::string gnuplotPreamble(const std::string& name, int width = 1000, int height = 650);

/// Writes `script` to directory/<name>.gp (atomically) and runs gnuplot on it in `directory`.
/// Returns the PNG written, or nothing when gnuplot is not installed; throws std::runtime_error
/// naming the script when gnuplot fails. `name` must be a plain file name (the caller's).
std::optional<std::filesystem::path> plotPng(const std::filesystem::path& directory, const std::string& name,
                                             const std::string& script);

}  // namespace sqdem
