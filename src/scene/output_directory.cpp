#include "sqdem/scene/output_directory.hpp"

#include <signal.h>

#include <cerrno>
#include <regex>
#include <vector>

#include "sqdem/scene/scene.hpp"

namespace sqdem {

bool ownsFile(const std::string& file, const std::string& name) {
  static const std::regex rest(R"((_from_step[0-9]+)?(\.csv|_final_particles\.csv|_(particles|surfaces|contacts|walls)(_[0-9]+){0,2}\.(vtu|vtp|pvtp|pvd)|_view\.py)"
                               R"(|_compression\.(csv|gp|png(\.tmp)?))"
                               R"(|_(after_[A-Za-z0-9_.-]+|latest)\.checkpoint)(\.tmp[0-9]+)?)");
  return file.rfind(name, 0) == 0 && std::regex_match(file.substr(name.size()), rest);
}

void prepareOutputDirectory(const std::filesystem::path& dir, const std::string& name, bool fresh, bool overwrite) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(dir, error) && !fs::is_directory(dir, error)) throw SceneError(dir.string() + ": --out is not a directory");
  fs::create_directories(dir, error);
  if (error) throw SceneError(dir.string() + ": cannot create the output directory: " + error.message());
  static const std::regex temporary(R"(.*\.tmp([0-9]+))");
  std::vector<fs::path> clash;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string file = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(file, m, temporary) && entry.is_regular_file()) {
      const long pid = std::strtol(m[1].str().c_str(), nullptr, 10);
      if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
        fs::remove(entry.path(), error);
        continue;
      }
    }
    if (fresh || ownsFile(file, name)) clash.push_back(entry.path());
  }
  if (clash.empty()) return;
  if (!overwrite) {
    throw SceneError(dir.string() + ": the output directory already holds " + std::to_string(clash.size()) + " file(s) (" +
                     clash.front().filename().string() + ", ...): choose another --out, or add --overwrite to remove "
                     "sqdem's files named " + name + "_* there first");
  }
  for (const fs::path& file : clash) {
    if (ownsFile(file.filename().string(), name)) fs::remove(file, error);
  }
}

}  // namespace sqdem
