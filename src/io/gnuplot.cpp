#include "sqdem/io/gnuplot.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>

#include "sqdem/archive/atomic_file.hpp"
#include "sqdem/io/plain_name.hpp"

namespace sqdem {
namespace {

/// Runs `gnuplot -e "output='<output>'" script` in `directory`; gnuplot's exit status, or -1
/// when gnuplot is not installed.
int runGnuplot(const std::filesystem::path& directory, const std::string& script, const std::string& output) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
  std::string program = "gnuplot", option = "-e", assignment = "output='" + output + "'", argument = script;
  char* argv[] = {program.data(), option.data(), assignment.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return 1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace

std::string gnuplotPreamble(const std::string& name, int width, int height) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) + " enhanced font ',11'\n" +
         "# sqdem sets 'output' to a temporary name and renames the PNG when gnuplot succeeded\n" +
         "if (!exists(\"output\")) output = '" + name + ".png'\n" + "set output output\n";
}

std::optional<std::filesystem::path> plotPng(const std::filesystem::path& directory, const std::string& name,
                                             const std::string& script) {
  // The name is in the script as text: only a plain file name may get there.
  if (!isPlainName(name)) throw std::runtime_error("'" + name + "': a plot's name must be letters, digits, _ . -");
  writeFileAtomically(directory / (name + ".gp"), script);
  const std::string temporary = name + ".png.tmp";
  const int status = runGnuplot(directory, name + ".gp", temporary);
  if (status < 0) return std::nullopt;
  if (status != 0) {
    std::filesystem::remove(directory / temporary);
    throw std::runtime_error("gnuplot failed on " + (directory / (name + ".gp")).string());
  }
  std::filesystem::rename(directory / temporary, directory / (name + ".png"));
  return directory / (name + ".png");
}

}  // namespace sqdem
