#include "sqdem/interaction/simd_path.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace sqdem {
namespace {

constexpr std::array<std::string_view, 3> names{"scalar", "baseline", "avx2"};

}  // namespace

std::vector<SimdPath> availableSimdPaths() {
  std::vector<SimdPath> paths{SimdPath::Scalar, SimdPath::Baseline};
#if defined(__x86_64__)
  // libgcc's CPU model: the instructions and the operating system's support of their registers.
  if (__builtin_cpu_supports("x86-64-v3")) paths.push_back(SimdPath::Avx2);
#endif
  return paths;
}

bool runsHere(SimdPath path) {
  const std::vector<SimdPath> paths = availableSimdPaths();
  return std::find(paths.begin(), paths.end(), path) != paths.end();
}

SimdPath widestSimdPath() { return availableSimdPaths().back(); }

std::string_view simdPathName(SimdPath path) { return names[static_cast<std::size_t>(path)]; }

SimdPath runnableSimdPath(std::string_view name) {
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == name && runsHere(static_cast<SimdPath>(k))) return static_cast<SimdPath>(k);
  }
  std::string message(1, '\'');
  message.append(name).append("': expected a SIMD path this CPU runs:");
  for (const SimdPath path : availableSimdPaths()) message.append(path == SimdPath::Scalar ? " " : ", ").append(simdPathName(path));
  throw std::invalid_argument(message);
}

}  // namespace sqdem
