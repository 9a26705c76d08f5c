#pragma once
// The code paths of the kernels that compute several contacts per instruction
// (docs/performance.md, "SIMD across contacts"), chosen at run time from what the CPU offers, so
// that one portable binary runs everywhere. Every path computes the same operations in the same
// order on each contact (the build contracts nothing into fused multiply-adds, CMakeLists.txt),
// so all of them give the same bits as the contact-by-contact kernels: the path changes the
// speed, never a result.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace sqdem {

enum class SimdPath : std::uint8_t {
  Scalar,    ///< contact by contact: the reference the others are tested against
  Baseline,  ///< two contacts per instruction in the instruction set the build targets (x86-64's default: SSE2)
  Avx2,      ///< four, in x86-64-v3's instruction set (AVX2 and its companions; x86-64 builds only)
};

/// The paths this CPU (and its operating system) runs, narrowest first.
std::vector<SimdPath> availableSimdPaths();
/// Whether path is one of them.
bool runsHere(SimdPath path);
/// The widest of them: what a World uses unless told otherwise.
SimdPath widestSimdPath();
/// "scalar", "baseline", "avx2".
std::string_view simdPathName(SimdPath path);
/// The path of that name when this CPU runs it; std::invalid_argument naming the paths it runs
/// otherwise (the CLI's --simd and the Python module's simd=).
SimdPath runnableSimdPath(std::string_view name);

}  // namespace sqdem
