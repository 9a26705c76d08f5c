#include "sqdem/archive/checkpoint_file.hpp"

#include <boost/crc.hpp>

#include <cstring>
#include <fstream>
#include <iterator>

#include "sqdem/archive/atomic_file.hpp"

namespace sqdem {
namespace {

constexpr char magic[8] = {'s', 'q', 'd', 'e', 'm', 'C', 'K', 'P'};
constexpr std::uint32_t formatVersion = 10;
constexpr std::size_t headerSize = sizeof magic + 4 + 8 + 8 + 8 + 4;
constexpr std::uint64_t largestPayload = std::uint64_t{1} << 40;  // 1 TiB: anything larger is corrupt

using Crc64 = boost::crc_optimal<64, 0x42F0E1EBA9EA3693ull, 0, 0, false, false>;

std::uint32_t crc32(std::string_view data) {
  boost::crc_32_type crc;
  crc.process_bytes(data.data(), data.size());
  return crc.checksum();
}

template <typename T>
T field(std::string_view header, std::size_t& at) {
  T value;
  std::memcpy(&value, header.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

}  // namespace

Fingerprint& Fingerprint::bytes(const void* data, std::size_t size) {
  Crc64 crc(state_);
  crc.process_bytes(data, size);
  state_ = crc.checksum();
  return *this;
}

Fingerprint& Fingerprint::operator()(std::string_view s) {
  (*this)(static_cast<std::uint64_t>(s.size()));
  return bytes(s.data(), s.size());
}

void writeCheckpointFile(const std::filesystem::path& path, const CheckpointStamp& stamp, std::string_view payload) {
  CheckpointWriter header;
  header.put(magic);
  header.put(formatVersion);
  header.put(stamp.build);
  header.put(stamp.scene);
  header.put(static_cast<std::uint64_t>(payload.size()));
  header.put(crc32(payload));
  writeFileAtomically(path, header.bytes() + std::string(payload));
}

CheckpointContents readCheckpointFile(const std::filesystem::path& path, std::uint64_t build) {
  const auto fail = [&](const std::string& what) { return CheckpointError(path.string() + ": " + what); };
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw fail("not a checkpoint file (missing, or not a regular file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open the checkpoint");
  std::string header(headerSize, '\0');
  in.read(header.data(), static_cast<std::streamsize>(headerSize));
  if (!in || std::memcmp(header.data(), magic, sizeof magic) != 0) throw fail("not an sqdem checkpoint (no header)");
  std::size_t at = sizeof magic;
  const auto version = field<std::uint32_t>(header, at);
  const auto writer = field<std::uint64_t>(header, at);
  const auto scene = field<std::uint64_t>(header, at);
  const auto size = field<std::uint64_t>(header, at);
  const auto crc = field<std::uint32_t>(header, at);
  if (version != formatVersion) {
    throw fail("checkpoint format " + std::to_string(version) + ", this build reads format " + std::to_string(formatVersion));
  }
  if (writer != build) throw fail("written by another build of sqdem (its record layout differs); rerun the scene");
  const auto fileSize = std::filesystem::file_size(path, error);
  if (error || size > largestPayload || fileSize != headerSize + size) {
    throw fail("checkpoint is truncated or padded (header announces " + std::to_string(size) + " payload bytes, file has " +
               std::to_string(error ? 0 : fileSize - headerSize) + ")");
  }
  std::string payload(size, '\0');
  in.read(payload.data(), static_cast<std::streamsize>(size));
  if (!in) throw fail("cannot read the checkpoint's payload");
  if (crc32(payload) != crc) throw fail("checkpoint is corrupt (checksum mismatch)");
  return {scene, std::move(payload)};
}

}  // namespace sqdem
