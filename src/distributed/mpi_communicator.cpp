#include "sqdem/distributed/mpi_communicator.hpp"

#include <mpi.h>

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
    for (std::size_t k = 0; k < values.size(); ++k) {
      values[k] = ExactSum::fromLimbs(std::span<const std::int64_t, n>(limbs.data() + k * n, n), nonFinite[k]);
    }
  }
  void sum(std::span<long long> values) const override { reduce(values.data(), values.size(), MPI_LONG_LONG, MPI_SUM); }
  void max(std::span<double> values) const override { reduce(values.data(), values.size(), MPI_DOUBLE, MPI_MAX); }
  void min(std::span<double> values) const override { reduce(values.data(), values.size(), MPI_DOUBLE, MPI_MIN); }

 private:
  static void reduce(void* data, std::size_t count, MPI_Datatype type, MPI_Op op) {
    if (count == 0) return;
    check(MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(count), type, op, MPI_COMM_WORLD), "MPI_Allreduce");
  }
  int rank_ = 0, size_ = 1;
  bool owner_ = false;
};

}  // namespace

std::shared_ptr<Communicator> worldCommunicator() {
  static const std::shared_ptr<Communicator> world = std::make_shared<MpiCommunicator>();  // MPI starts once
  return world;
}

}  // namespace sqdem
