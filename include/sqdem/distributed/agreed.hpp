#pragma once
// A failure that may happen on some ranks only, made every rank's (collective): a rank that met
// it alone would otherwise go on into a collective call the others never reach.

#include <string>
#include <utility>
#include <vector>

#include "sqdem/distributed/communicator.hpp"

namespace sqdem {

/// Runs `part`, which may throw Error (constructible from its message) on some ranks only; when
/// it threw on any rank, every rank throws Error with the lowest failing rank's message.
template <typename Error, typename Part>
void agreed(const Communicator& ranks, Part&& part) {
  if (ranks.size() == 1) return std::forward<Part>(part)();
  std::string error;
  bool failed = false;
  try {
    std::forward<Part>(part)();
  } catch (const Error& e) {
    error = e.what();
    failed = true;
  }
  const double lowest = ranks.min(failed ? static_cast<double>(ranks.rank()) : static_cast<double>(ranks.size()));
  if (lowest == ranks.size()) return;
  std::vector<std::string> outbox(static_cast<std::size_t>(ranks.size()));
  if (lowest == ranks.rank()) outbox.assign(outbox.size(), error);
  throw Error(ranks.exchangeAll(std::move(outbox))[static_cast<std::size_t>(lowest)]);
}

}  // namespace sqdem
