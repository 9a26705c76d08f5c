#include "sqdem/mechanics/true_gap_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sqdem/mechanics/hertz_law.hpp"

namespace sqdem {

double TrueGapRungs::overlap(int k) const { return std::ldexp(length, k); }

int TrueGapRungs::segment(double delta) const {
  // floor(log2(delta / length)) exactly, as the exponent of delta / length (log2 itself rounds
  // up to the rung's k just below a rung), for a fraction of the cost (docs/performance.md,
  // "Cheaper rungs, second round"); +infinity clamps to the highest segment.
  return std::clamp(std::ilogb(delta / length), lowest, lowest + count - 2);
}

bool TrueGapRungs::holds(double delta) const {
  return weight == 0.0 || !(delta > 0.0) || hasSegment(segment(delta));
}

bool TrueGapRungs::holdAfterTurning(double delta, double tilt1, double tilt2, double tolerance) const {
  if (weight == 0.0 || !(delta > 0.0)) return true;
  const int k = segment(delta), upper = has(k + 1) ? k + 1 : k;
  if (!has(upper)) return true;
  const TrueGapRung& r = rung[upper - lowest];
  return std::abs(tilt1) * r.reach2 + std::abs(tilt2) * r.reach1 <= tolerance * delta;
}

void TrueGapRungs::set(int k, double rungForce, double rungArea, double rungReach1, double rungReach2) {
  if (!(rungForce > 0.0 && rungArea > 0.0 && rungReach1 >= 0.0 && rungReach2 >= 0.0)) {
    throw std::invalid_argument("TrueGapRungs::set: a rung's force and area must be > 0, its reaches >= 0");
  }
  rung[k - lowest] = {rungForce, rungArea, static_cast<float>(rungReach1), static_cast<float>(rungReach2)};
  solved |= 1u << (k - lowest);
}

double trueGapWeight(double n1A, double n2A, double n1B, double n2B) {
  const double furthest = std::max({std::abs(n1A - 2.0), std::abs(n2A - 2.0), std::abs(n1B - 2.0), std::abs(n2B - 2.0)});
  return std::min(1.0, furthest / 0.5);
}

TrueGapLaw TrueGapLaw::read(const LawInput& in, const PairElasticity&) {
  TrueGapLaw law;
  if (in.has("cells")) {
    const double cells = in.number("cells");
    if (!(cells >= fewestCells && cells <= mostCells) || cells != std::floor(cells)) {
      in.fail("cells", "must be an integer in [" + std::to_string(fewestCells) + ", " + std::to_string(mostCells) +
                           "] (cells per side of the coarse grid)");
    }
    law.cells = static_cast<int>(cells);
  }
  if (in.has("gap_tolerance")) {
    law.gapTolerance = in.number("gap_tolerance");
    if (!(law.gapTolerance >= 0.0 && law.gapTolerance <= 1.0)) {
      in.fail("gap_tolerance", "must be in [0, 1] (the change of the gap across the contact, as a fraction of the overlap, at which "
                               "a turn of the bodies re-solves its rungs)");
    }
  }
  return law;
}

namespace {

/// The weight of the rungs handed on: 0 (elliptic Hertz) without them or where the ones up to
/// `last` are not all solved.
double solvedWeight(const TrueGapRungs* rungs, int last) {
  if (rungs == nullptr) return 0.0;
  for (int k = TrueGapRungs::lowest; k <= last; ++k) {
    if (!rungs->has(k)) return 0.0;
  }
  return rungs->weight;
}

}  // namespace

NormalResponse TrueGapLaw::force(const NormalContact& c, double overlap, History&) const {
  if (!(overlap > 0.0)) return {.acting = false};
  const int k = c.trueGap != nullptr ? c.trueGap->segment(overlap) : 0, i = k - TrueGapRungs::lowest;
  const double w = c.trueGap != nullptr && c.trueGap->hasSegment(k) ? c.trueGap->weight : 0.0;
  HertzLaw::History none;
  const NormalResponse hertz = w < 1.0 ? HertzLaw{}.force(c, overlap, none) : NormalResponse{};
  if (w == 0.0) return hertz;
  const TrueGapRung &low = c.trueGap->rung[i], &high = c.trueGap->rung[i + 1];
  const double s = overlap / c.trueGap->overlap(k), m = std::log2(high.force / low.force), force = low.force * std::pow(s, m);
  const double area = low.area * std::pow(s, std::log2(high.area / low.area));
  return {.force = (1.0 - w) * hertz.force + w * force,
          .stiffness = (1.0 - w) * hertz.stiffness + w * m * force / overlap,
          .area = (1.0 - w) * hertz.area + w * area};
}

double TrueGapLaw::energy(const NormalContact& c, double overlap) const {
  if (!(overlap > 0.0)) return 0.0;
  const int top = c.trueGap != nullptr ? c.trueGap->segment(overlap) : 0;
  const double w = solvedWeight(c.trueGap, top + 1);
  HertzLaw::History none;
  const double hertz = w < 1.0 ? 0.4 * HertzLaw{}.force(c, overlap, none).force * overlap : 0.0;  // 2/5 F delta (hertz_law.hpp)
  if (w == 0.0) return hertz;
  const TrueGapRungs& r = *c.trueGap;
  double sum = 0.0;
  for (int k = TrueGapRungs::lowest; k <= top; ++k) {
    const TrueGapRung &low = r.rung[k - TrueGapRungs::lowest], &high = r.rung[k + 1 - TrueGapRungs::lowest];
    const double m = std::log2(high.force / low.force), start = r.overlap(k);
    const double end = k == top ? overlap : r.overlap(k + 1), from = k == TrueGapRungs::lowest ? 0.0 : 1.0;
    sum += low.force * start / (m + 1.0) * (std::pow(end / start, m + 1.0) - from);
  }
  return (1.0 - w) * hertz + w * sum;
}

}  // namespace sqdem
