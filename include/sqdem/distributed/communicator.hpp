#pragma once
// The reduction seam (docs/architecture.md, "Reductions", "Ghosts"): every quantity of a run that is a sum,
// maximum or decision over all particles or contacts — wall and body loads, the kinetic energy,
// the neighbour-list rebuild decision, run health, the energy ledger, packing measures, stress,
// servos and stop criteria, progress — is reduced through a Communicator, and only through it.
// In one process (SerialCommunicator) every call returns its input: the seam costs a virtual
// call per reduction. Across MPI ranks (mpi_communicator.hpp, its own target: MPI's headers stay
// out of the engine) the sums are exact (ExactSum), so their bits do not depend on how the
// particles are divided between ranks. The same seam carries the messages between ranks: the
// particles that migrate and their ghosts (byte strings, written and read as records).

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "sqdem/math/exact_sum.hpp"

namespace sqdem {

class Communicator {
 public:
  virtual ~Communicator() = default;

  /// The messages this process sent to other ranks and their bytes, and the reductions over all
  /// ranks it took part in (each one all-reduce), since it started.
  struct Traffic {
    long long messages = 0;
    long long bytes = 0;
    long long reductions = 0;
  };
  const Traffic& traffic() const { return traffic_; }

  virtual int rank() const = 0;
  virtual int size() const = 0;

  /// Each value replaced by its sum over the ranks.
  virtual void sum(std::span<ExactSum> values) const = 0;
  virtual void sum(std::span<long long> values) const = 0;
  /// Each value replaced by its maximum (minimum) over the ranks.
  virtual void max(std::span<double> values) const = 0;
  virtual void min(std::span<double> values) const = 0;

  /// All to all (collective): outbox[r] goes to rank r, this one included; returns what every
  /// rank sent this one (inbox[r] from rank r). For the rare exchanges (migration, choosing the
  /// ghosts), when a rank does not know who will send to it.
  virtual std::vector<std::string> exchangeAll(std::vector<std::string> outbox) const = 0;
  /// Between neighbours: sends every (rank, bytes) of outbox and returns one message from each
  /// rank of `from`, in that order; every message sent must be expected by its receiver (the
  /// ghosts' refreshes and loads of every step, between the partners of the last rebuild).
  virtual std::vector<std::string> exchange(const std::vector<std::pair<int, std::string>>& outbox,
                                            std::span<const int> from) const = 0;

  /// Ends every rank's process with exit code `code` (a failure one rank met alone, where the
  /// others would wait for it in a collective).
  [[noreturn]] virtual void abort(int code) const = 0;

  /// Every rank's bytes on rank 0, in rank order (of any size: a checkpoint's whole state); the
  /// others get none. Collective.
  virtual std::vector<std::string> gather(std::string bytes) const = 0;

  /// Whether any rank's value is true.
  bool any(bool value) const {
    double v = value ? 1.0 : 0.0;
    max(std::span(&v, 1));
    return v > 0.0;
  }
  /// A process's exact share summed over the ranks, rounded once (a share rounded first would
  /// make the result depend on the decomposition).
  double sum(ExactSum share) const {
    sum(std::span(&share, 1));
    return share.value();
  }
  double max(double value) const {
    max(std::span(&value, 1));
    return value;
  }
  double min(double value) const {
    min(std::span(&value, 1));
    return value;
  }
  long long sum(long long value) const {
    sum(std::span(&value, 1));
    return value;
  }

 protected:
  mutable Traffic traffic_;  ///< counted by the exchanges
};

/// One process: the ranks' reduction is the process's own value.
class SerialCommunicator final : public Communicator {
 public:
  using Communicator::max, Communicator::min, Communicator::sum;
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void sum(std::span<ExactSum>) const override {}
  void sum(std::span<long long>) const override {}
  void max(std::span<double>) const override {}
  void min(std::span<double>) const override {}
  [[noreturn]] void abort(int code) const override { std::exit(code); }
  std::vector<std::string> gather(std::string bytes) const override { return {std::move(bytes)}; }
  std::vector<std::string> exchangeAll(std::vector<std::string> outbox) const override { return outbox; }
  std::vector<std::string> exchange(const std::vector<std::pair<int, std::string>>& outbox,
                                    std::span<const int> from) const override {
    std::vector<std::string> inbox;
    for (std::size_t k = 0; k < from.size(); ++k) inbox.push_back(k < outbox.size() ? outbox[k].second : std::string());
    return inbox;
  }
};

}  // namespace sqdem
