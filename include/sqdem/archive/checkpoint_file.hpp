#pragma once
// Checkpoint files (docs/architecture.md, "Stores"): a fixed header, then the payload (the run's
// progress and the World's state, world_state.cpp). The header makes a checkpoint self-checking:
//
//   magic "sqdemCKP" | format version (u32) | build fingerprint (u64) | scene fingerprint (u64)
//   | payload size (u64) | payload CRC-32 (u32) | payload
//
// The format version is the header's; the build fingerprint is the writer's (World::
// stateFingerprint: the payload's version and the byte layout of every record written raw; a
// checkpoint is a restart file for the same build, not an archive); the scene fingerprint is a
// hash of the validated scene's parts but its stages (scene/scene_fingerprint.hpp), which the
// reader compares with its own. A corrupted, truncated or other-build file is refused with one message (CheckpointError)
// before any of its payload is used.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace sqdem {

class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws CheckpointError "checkpoint is corrupt (what)" unless ok: the check of every count and
/// index a reader follows.
inline void requireIntact(bool ok, const char* what) {
  if (!ok) throw CheckpointError(std::string("checkpoint is corrupt (") + what + ")");
}

/// Incremental 64-bit hash (CRC-64/ECMA-182 through Boost.CRC) of a sequence of values.
class Fingerprint {
 public:
  Fingerprint& bytes(const void* data, std::size_t size);
  Fingerprint& operator()(double v) { return bytes(&v, sizeof v); }
  Fingerprint& operator()(std::uint64_t v) { return bytes(&v, sizeof v); }
  Fingerprint& operator()(std::string_view s);
  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 0;
};

/// Writes a checkpoint payload value by value (CheckpointReader reads it back).
class CheckpointWriter {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_destructible_v<T>);  // plain data (Eigen types are not trivially copyable by trait)
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  /// A vector as its size then its elements.
  template <typename T>
  void putVector(const std::vector<T>& v) {
    putPrefix(v, v.size());
  }
  /// The first n elements of a vector, as putVector writes a vector of n.
  template <typename T>
  void putPrefix(const std::vector<T>& v, std::size_t n) {
    static_assert(std::is_trivially_destructible_v<T>);
    put(static_cast<std::uint64_t>(n));
    bytes_.append(reinterpret_cast<const char*>(v.data()), n * sizeof(T));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

/// Reads a checkpoint payload value by value: every read is bounded by the bytes left, so a
/// corrupt count can neither read past the end nor allocate more than the file holds.
class CheckpointReader {
 public:
  explicit CheckpointReader(std::string_view payload) : data_(payload) {}

  template <typename T>
  void get(T& value) {
    static_assert(std::is_trivially_destructible_v<T>);  // plain data (Eigen types are not trivially copyable by trait)
    take(&value, sizeof(T));
  }
  /// A vector written as its size then its elements; at most `limit` elements.
  template <typename T>
  void getVector(std::vector<T>& v, std::uint64_t limit) {
    static_assert(std::is_trivially_destructible_v<T>);  // plain data (Eigen types are not trivially copyable by trait)
    std::uint64_t n = 0;
    get(n);
    if (n > limit || n > left() / sizeof(T)) throw CheckpointError("checkpoint is corrupt (implausible array size)");
    v.resize(n);
    take(v.data(), n * sizeof(T));
  }
  std::size_t left() const { return data_.size() - at_; }

 private:
  void take(void* out, std::size_t size) {
    if (size > left()) throw CheckpointError("checkpoint is truncated");
    std::memcpy(out, data_.data() + at_, size);
    at_ += size;
  }
  std::string_view data_;
  std::size_t at_ = 0;
};

/// What a checkpoint must have been written by and for.
struct CheckpointStamp {
  std::uint64_t build = 0;  ///< the payload's version and record layouts
  std::uint64_t scene = 0;  ///< the validated scene
};

/// Writes header + payload atomically (a crash leaves the previous file or none).
void writeCheckpointFile(const std::filesystem::path& path, const CheckpointStamp& stamp, std::string_view payload);

/// What a checkpoint file holds: the scene fingerprint it was written for (its reader's to
/// compare) and its payload.
struct CheckpointContents {
  std::uint64_t scene = 0;
  std::string payload;
};

/// Reads a checkpoint after checking every header field, the build fingerprint `build` and the
/// CRC; throws CheckpointError("<path>: <what is wrong>").
CheckpointContents readCheckpointFile(const std::filesystem::path& path, std::uint64_t build);

}  // namespace sqdem
