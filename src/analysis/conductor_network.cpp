#include "sqdem/analysis/conductor_network.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "sqdem/analysis/spd_solve.hpp"

namespace sqdem {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// A link seen from one of its nodes: the other node, the periods of its image along the axis
/// (as seen from this node) and the link.
struct Neighbour {
  std::uint32_t node;
  int shift;
  std::uint32_t link;
};

/// Each node's neighbours, in link order (compressed rows).
struct Adjacency {
  std::vector<std::uint32_t> start;
  std::vector<Neighbour> entries;

  Adjacency(const ConductorNetwork& network, int axis) : start(network.nodes + 1, 0), entries(2 * network.links.size()) {
    for (const ConductorNetwork::Link& l : network.links) {
      ++start[l.a + 1];
      ++start[l.b + 1];
    }
    for (std::size_t i = 0; i < network.nodes; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::uint32_t k = 0; k < network.links.size(); ++k) {
      const ConductorNetwork::Link& l = network.links[k];
      entries[next[l.a]++] = {l.b, l.shift[axis], k};
      entries[next[l.b]++] = {l.a, -l.shift[axis], k};
    }
  }
  std::span<const Neighbour> of(std::size_t node) const { return {entries.data() + start[node], entries.data() + start[node + 1]}; }
};

void check(const ConductorNetwork& network, int axis) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("solveConduction: the axis must be 0, 1 or 2");
  if (!(network.box.minCoeff() > 0.0)) throw std::invalid_argument("solveConduction: the box's edges must be > 0");
  for (const ConductorNetwork::Link& l : network.links) {
    if (l.a >= network.nodes || l.b >= network.nodes) throw std::invalid_argument("solveConduction: a link to a missing node");
    if (!(l.conductance > 0.0 && std::isfinite(l.conductance))) throw std::invalid_argument("solveConduction: a link's conductance must be finite and > 0");
  }
  for (int d = 0; d < 3; ++d) {
    for (const auto* side : {&network.low[d], &network.high[d]}) {
      for (const ConductorNetwork::Terminal& t : *side) {
        if (t.node >= network.nodes) throw std::invalid_argument("solveConduction: a terminal of a missing node");
        if (!(t.conductance > 0.0)) throw std::invalid_argument("solveConduction: a terminal's conductance must be > 0");
        if (network.periodic[d]) throw std::invalid_argument("solveConduction: a terminal on periodic axis " + std::to_string(d));
      }
    }
  }
}

}  // namespace

NetworkConduction solveConduction(const ConductorNetwork& network, int axis, double tolerance) {
  check(network, axis);
  const std::size_t n = network.nodes;
  const bool periodic = network.periodic[axis];
  const double dV = 1.0, length = network.box[axis];
  const Adjacency adjacency(network, axis);
  NetworkConduction result;
  result.axis = axis;
  result.potential.assign(n, nan);
  result.current.assign(network.links.size(), 0.0);

  // Electrodes: per node its finite terminals' conductances and whether it is held ideally.
  std::vector<double> toLow(n, 0.0), toHigh(n, 0.0), held(n, nan);
  if (!periodic) {
    for (const ConductorNetwork::Terminal& t : network.low[axis]) {
      if (std::isinf(t.conductance)) held[t.node] = dV; else toLow[t.node] += t.conductance;
    }
    for (const ConductorNetwork::Terminal& t : network.high[axis]) {
      if (!std::isinf(t.conductance)) { toHigh[t.node] += t.conductance; continue; }
      if (held[t.node] == dV) throw std::invalid_argument("solveConduction: node " + std::to_string(t.node) + " joins both electrodes ideally (a short circuit)");
      held[t.node] = 0.0;
    }
  }
  const auto touchesLow = [&](std::size_t i) { return toLow[i] > 0.0 || held[i] == dV; };
  const auto touchesHigh = [&](std::size_t i) { return toHigh[i] > 0.0 || held[i] == 0.0; };

  // The clusters, by a flood from each node not yet reached: periods counted along the axis
  // (a cluster wraps when a loop adds up to a period), the unwrapped coordinate a first guess.
  std::vector<std::int64_t> period(n, 0), cluster(n, -1);
  std::vector<double> coordinate(n, 0.0);
  std::vector<std::uint8_t> carries;  // per cluster
  std::vector<std::uint32_t> root;    // per cluster: its first node (pinned when periodic)
  std::vector<std::uint32_t> front;
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (cluster[seed] >= 0) continue;
    const auto c = static_cast<std::int64_t>(root.size());
    root.push_back(seed);
    bool wraps = false, low = false, high = false;
    cluster[seed] = c;
    front.assign(1, seed);
    while (!front.empty()) {
      const std::uint32_t i = front.back();
      front.pop_back();
      low = low || touchesLow(i);
      high = high || touchesHigh(i);
      for (const Neighbour& e : adjacency.of(i)) {
        const double step = network.links[e.link].branch[axis] * (network.links[e.link].a == i ? 1.0 : -1.0);
        if (cluster[e.node] < 0) {
          cluster[e.node] = c;
          period[e.node] = period[i] + e.shift;
          coordinate[e.node] = coordinate[i] + step;
          front.push_back(e.node);
        } else if (period[e.node] != period[i] + e.shift) {
          wraps = true;
        }
      }
    }
    carries.push_back(periodic ? wraps : (low && high));
  }

  // The unknowns: the carrying clusters' nodes but the held (and, periodic, each cluster's root).
  std::vector<std::int64_t> unknown(n, -1);
  std::int64_t count = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!carries[cluster[i]]) continue;
    ++result.carryingNodes;
    if (periodic && root[cluster[i]] == i) held[i] = 0.0;
    if (std::isnan(held[i])) unknown[i] = count++;
  }
  result.percolates = result.carryingNodes > 0;
  if (!result.percolates) return result;

  // Kirchhoff's law per unknown node: sum_l g (phi_i - phi_j + s dV) + terminals = 0.
  SpdRows A;
  std::vector<double> b(static_cast<std::size_t>(count), 0.0), guess(static_cast<std::size_t>(count), 0.0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::int64_t u = unknown[i];
    if (u < 0) continue;
    if (periodic) guess[u] = -dV * (coordinate[i] - coordinate[root[cluster[i]]]) / length;
    double diagonal = toLow[i] + toHigh[i];
    b[u] += toLow[i] * dV;
    for (const Neighbour& e : adjacency.of(i)) {
      if (e.node == i) continue;  // a link to its own image carries s dV g and adds nothing here
      const double g = network.links[e.link].conductance;
      diagonal += g;
      b[u] -= g * e.shift * (periodic ? dV : 0.0);
      if (unknown[e.node] >= 0) A.add(unknown[e.node], -g); else b[u] += g * held[e.node];
    }
    A.add(u, diagonal);
    A.endRow();
  }
  const SpdSolution solution = solveSpd(A, b, guess, tolerance, count + 1000);
  result.iterations = solution.iterations;
  result.converged = solution.converged;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (unknown[i] >= 0) result.potential[i] = solution.x[unknown[i]];
    else if (carries[cluster[i]]) result.potential[i] = held[i];
  }

  // Currents; sigma_eff from the volume average (periodic) or the electrodes' currents.
  double moment = 0.0;
  std::vector<double> outflow(n, 0.0);  // through links
  for (std::size_t k = 0; k < network.links.size(); ++k) {
    const ConductorNetwork::Link& l = network.links[k];
    if (!carries[cluster[l.a]]) continue;
    const double jump = periodic ? l.shift[axis] * dV : 0.0;
    const double I = l.conductance * (result.potential[l.a] - result.potential[l.b] + jump);
    result.current[k] = I;
    moment += I * l.branch[axis];
    outflow[l.a] += I;
    outflow[l.b] -= I;
  }
  const double volume = network.box.prod();
  if (periodic) {
    result.conductivity = moment / volume * length / dV;
    return result;
  }
  double in = 0.0, out = 0.0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!carries[cluster[i]]) continue;
    const double phi = result.potential[i];
    const double intoLow = toLow[i] * (phi - dV), intoHigh = toHigh[i] * phi;  // out of the node, finite terminals
    if (held[i] == dV) in += outflow[i] + intoLow + intoHigh;  // what its ideal joint delivers
    else in -= intoLow;
    if (held[i] == 0.0) out -= outflow[i] + intoLow + intoHigh;
    else out += intoHigh;
  }
  result.conductivity = in * length / (volume / length * dV);
  result.currentImbalance = std::abs(in - out) / in;
  return result;
}

}  // namespace sqdem
