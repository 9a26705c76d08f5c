#include "sqdem/mechanics/law_input.hpp"

#include <stdexcept>

namespace sqdem {

std::string joinKeys(std::span<const std::string_view> keys) {
  std::string out;
  for (const std::string_view k : keys) out += std::string(out.empty() ? "" : ", ") + std::string(k);
  return out;
}

void LawInput::fail(std::string_view key, const std::string& message) const {
  raise(key, message);
  throw std::logic_error("LawInput::raise returned");
}

double LawInput::positive(std::string_view key, const char* unit) const {
  const double x = number(key);
  if (!(x > 0.0)) fail(key, std::string("must be > 0 (") + unit + ")");
  return x;
}

double LawInput::positive(std::string_view key, const char* unit, double fallback) const {
  return has(key) ? positive(key, unit) : fallback;
}

}  // namespace sqdem
