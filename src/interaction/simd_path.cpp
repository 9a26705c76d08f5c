#include "sqdem/interaction/simd_path.hpp"

#include <algorithm>
#include <array>

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

std::optional<SimdPath> simdPathNamed(std::string_view name) {
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == name) return static_cast<SimdPath>(k);
  }
  return std::nullopt;
}

}  // namespace sqdem
