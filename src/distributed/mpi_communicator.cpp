#include "sqdem/distributed/mpi_communicator.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace sqdem {
namespace {

void check(int code, const char* call) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

class MpiCommunicator final : public Communicator {
 public:
  using Communicator::max, Communicator::min, Communicator::sum;

  MpiCommunicator() {
    int initialised = 0;
    check(MPI_Initialized(&initialised), "MPI_Initialized");
    if (!initialised) {
      int provided = 0;
      check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
      owner_ = true;
    }
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
  }
  ~MpiCommunicator() override {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (owner_ && !finalised) MPI_Finalize();
  }
  MpiCommunicator(const MpiCommunicator&) = delete;
  MpiCommunicator& operator=(const MpiCommunicator&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void sum(std::span<ExactSum> values) const override {
    if (values.empty()) return;
    constexpr int n = ExactSum::limbCount;
    std::vector<std::int64_t> limbs(values.size() * n);
    std::vector<double> nonFinite(values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      const auto digits = values[k].limbs();
      std::copy(digits.begin(), digits.end(), limbs.begin() + static_cast<std::ptrdiff_t>(k * n));
      nonFinite[k] = values[k].nonFinite();
    }
    check(MPI_Allreduce(MPI_IN_PLACE, limbs.data(), static_cast<int>(limbs.size()), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
    // inf + inf, inf - inf and NaN give the same class in any order.
    check(MPI_Allreduce(MPI_IN_PLACE, nonFinite.data(), static_cast<int>(nonFinite.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
    traffic_.reductions += 2;
    for (std::size_t k = 0; k < values.size(); ++k) {
      values[k] = ExactSum::fromLimbs(std::span<const std::int64_t, n>(limbs.data() + k * n, n), nonFinite[k]);
    }
  }
  void sum(std::span<long long> values) const override { reduce(values.data(), values.size(), MPI_LONG_LONG, MPI_SUM); }
  void max(std::span<double> values) const override { reduce(values.data(), values.size(), MPI_DOUBLE, MPI_MAX); }
  void min(std::span<double> values) const override { reduce(values.data(), values.size(), MPI_DOUBLE, MPI_MIN); }

  [[noreturn]] void abort(int code) const override {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);  // MPI_Abort does not return
  }

  std::vector<std::string> exchangeAll(std::vector<std::string> outbox) const override {
    if (static_cast<int>(outbox.size()) != size_) throw std::logic_error("MPI: exchangeAll needs a message per rank");
    std::vector<long long> sent(size_), received(size_);
    for (int r = 0; r < size_; ++r) sent[r] = static_cast<long long>(outbox[r].size());
    check(MPI_Alltoall(sent.data(), 1, MPI_LONG_LONG, received.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD), "MPI_Alltoall");
    const std::vector<int> sendCount = counts(sent), receiveCount = counts(received);
    std::vector<int> sendAt(size_, 0), receiveAt(size_, 0);
    std::exclusive_scan(sendCount.begin(), sendCount.end(), sendAt.begin(), 0);
    std::exclusive_scan(receiveCount.begin(), receiveCount.end(), receiveAt.begin(), 0);
    std::string out, in(static_cast<std::size_t>(receiveAt.back() + receiveCount.back()), '\0');
    for (int r = 0; r < size_; ++r) {
      out += outbox[r];
      if (r != rank_ && !outbox[r].empty()) ++traffic_.messages, traffic_.bytes += static_cast<long long>(outbox[r].size());
    }
    check(MPI_Alltoallv(out.data(), sendCount.data(), sendAt.data(), MPI_BYTE, in.data(), receiveCount.data(),
                        receiveAt.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
    std::vector<std::string> inbox(size_);
    for (int r = 0; r < size_; ++r) inbox[r] = in.substr(receiveAt[r], receiveCount[r]);
    return inbox;
  }

  std::vector<std::string> gather(std::string bytes) const override {
    // Point to point, rank by rank, in pieces below MPI's int count: rank 0 holds one message at
    // a time besides what it gathered.
    std::vector<std::string> inbox;
    if (rank_ != 0) {
      const auto size = static_cast<std::uint64_t>(bytes.size());
      check(MPI_Send(&size, 1, MPI_UINT64_T, 0, gatherTag, MPI_COMM_WORLD), "MPI_Send");
      for (std::uint64_t at = 0; at < size; at += gatherPiece) {
        check(MPI_Send(bytes.data() + at, static_cast<int>(std::min(gatherPiece, size - at)), MPI_BYTE, 0, gatherTag,
                       MPI_COMM_WORLD),
              "MPI_Send");
      }
      ++traffic_.messages, traffic_.bytes += static_cast<long long>(size);
      return inbox;
    }
    inbox.push_back(std::move(bytes));
    for (int r = 1; r < size_; ++r) {
      std::uint64_t size = 0;
      check(MPI_Recv(&size, 1, MPI_UINT64_T, r, gatherTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
      std::string& message = inbox.emplace_back(size, '\0');
      for (std::uint64_t at = 0; at < size; at += gatherPiece) {
        check(MPI_Recv(message.data() + at, static_cast<int>(std::min(gatherPiece, size - at)), MPI_BYTE, r, gatherTag,
                       MPI_COMM_WORLD, MPI_STATUS_IGNORE),
              "MPI_Recv");
      }
    }
    return inbox;
  }

  std::vector<std::string> exchange(const std::vector<std::pair<int, std::string>>& outbox,
                                    std::span<const int> from) const override {
    std::vector<MPI_Request> sends(outbox.size());
    for (std::size_t k = 0; k < outbox.size(); ++k) {
      const std::string& m = outbox[k].second;
      ++traffic_.messages;
      traffic_.bytes += static_cast<long long>(m.size());
      check(MPI_Isend(m.data(), counts({static_cast<long long>(m.size())})[0], MPI_BYTE, outbox[k].first, exchangeTag,
                      MPI_COMM_WORLD, &sends[k]),
            "MPI_Isend");
    }
    std::vector<std::string> inbox(from.size());
    for (std::size_t k = 0; k < from.size(); ++k) {
      MPI_Message message;
      MPI_Status status;
      check(MPI_Mprobe(from[k], exchangeTag, MPI_COMM_WORLD, &message, &status), "MPI_Mprobe");
      int bytes = 0;
      check(MPI_Get_count(&status, MPI_BYTE, &bytes), "MPI_Get_count");
      inbox[k].resize(static_cast<std::size_t>(bytes));
      check(MPI_Mrecv(inbox[k].data(), bytes, MPI_BYTE, &message, MPI_STATUS_IGNORE), "MPI_Mrecv");
    }
    check(MPI_Waitall(static_cast<int>(sends.size()), sends.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
    return inbox;
  }

 private:
  /// Byte counts as MPI's int counts (a message, or a rank's messages together, below 2 GiB).
  static std::vector<int> counts(const std::vector<long long>& bytes) {
    if (std::accumulate(bytes.begin(), bytes.end(), 0LL) > INT_MAX) {
      throw std::runtime_error("MPI: more than 2 GiB in one exchange of particles (use more ranks)");
    }
    return {bytes.begin(), bytes.end()};
  }
  /// The tag of exchange()'s messages: each rank sends a partner at most one per call, and calls
  /// are collective in order, so messages match by source alone.
  static constexpr int exchangeTag = 7;
  /// gather()'s: rank 0 receives from each rank in turn, every piece in order.
  static constexpr int gatherTag = 8;
  static constexpr std::uint64_t gatherPiece = std::uint64_t{1} << 30;
  void reduce(void* data, std::size_t count, MPI_Datatype type, MPI_Op op) const {
    if (count == 0) return;
    check(MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(count), type, op, MPI_COMM_WORLD), "MPI_Allreduce");
    ++traffic_.reductions;
  }
  int rank_ = 0, size_ = 1;
  bool owner_ = false;
};

}  // namespace

std::shared_ptr<Communicator> worldCommunicator() {
  static const std::shared_ptr<Communicator> world = std::make_shared<MpiCommunicator>();  // MPI starts once
  return world;
}

std::shared_ptr<const Communicator> launchedRanks() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(variable) != nullptr) return worldCommunicator();
  }
  return std::make_shared<SerialCommunicator>();
}

}  // namespace sqdem
