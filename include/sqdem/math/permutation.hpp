#pragma once
// Re-ordering of parallel arrays: element k of the result is element order[k] of the input.

#include <cstdint>
#include <vector>

namespace sqdem {

template <typename T>
void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
  std::vector<T> out;
  out.reserve(order.size());
  for (const std::uint32_t old : order) out.push_back(values[old]);
  values = std::move(out);
}

}  // namespace sqdem
