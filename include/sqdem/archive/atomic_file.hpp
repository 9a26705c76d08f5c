#pragma once
// Atomic file output: the content goes to a temporary file in the same directory, which is then
// renamed over the target, so a reader (or a crash, or Ctrl-C) never sees a half-written file
// and an existing file is replaced only by a complete one.

#include <filesystem>
#include <functional>
#include <string_view>

namespace sqdem {

/// Writes `content` to `path` atomically; throws std::runtime_error naming the path on failure.
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

/// The same for a file that `write` writes to the temporary path it is given (and throws
/// std::runtime_error when it cannot).
void writeFileAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace sqdem
