#pragma once
// A plain name: 1 to maxLength letters, digits, '_', '.', '-', not starting with '.' or '-'.
// Names a user gives that end up in file names, CSV rows or plot scripts (stage names, a run's
// name from its scene file, a contact driver's name, a plot's) must be plain: they can then
// neither leave a directory nor be read as code.

#include <algorithm>
#include <cstddef>
#include <string_view>

namespace sqdem {

inline bool isPlainName(std::string_view s, std::size_t maxLength = std::string_view::npos) {
  const auto allowed = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
  };
  return !s.empty() && s.size() <= maxLength && s.front() != '.' && s.front() != '-' && std::all_of(s.begin(), s.end(), allowed);
}

}  // namespace sqdem
