#include "sqdem/truegap/true_gap_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sqdem/mechanics/hertz_law.hpp"
#include "sqdem/truegap/pair_contact.hpp"

namespace sqdem {

double trueGapWeight(const Superquadric& A, const Superquadric& B) {
  const double furthest = std::max({std::abs(A.n1() - 2.0), std::abs(A.n2() - 2.0), std::abs(B.n1() - 2.0), std::abs(B.n2() - 2.0)});
  return std::min(1.0, furthest / 0.5);
}

TrueGapCurve::TrueGapCurve(const PairGap& gap, const RelativeRadii& radii, double effectiveModulus, double weight, int cells)
    : gap_(gap), hertz_{radii, hertzFactors(radii.ratio(), EccentricityMethod::Exact), effectiveModulus}, weight_(weight), cells_(cells),
      rungs_(rungCount) {
  if (!(weight >= 0.0 && weight <= 1.0)) throw std::invalid_argument("TrueGapCurve: the weight must be in [0, 1]");
}

double TrueGapCurve::rungOverlap(int k) const { return std::ldexp(gap_.referenceLength(), k); }

const TrueGapCurve::Rung& TrueGapCurve::rung(int k) {
  Rung& r = rungs_[k - lowestRung];
  if (!r.solved) {
    const HalfspaceContact c = gapContact(gap_, rungOverlap(k), hertz_.effectiveModulus, cells_);
    r = {c.force, c.area, true};
  }
  return r;
}

int TrueGapCurve::segment(double overlap) const {
  const int k = static_cast<int>(std::floor(std::log2(overlap / gap_.referenceLength())));
  if (k >= lowestRung + rungCount - 1) {
    throw std::runtime_error("the true-gap law: an overlap of " + std::to_string(overlap / gap_.referenceLength()) +
                             " R_ref, beyond its range (below 0.5 R_ref)");
  }
  return std::max(k, lowestRung);
}

int TrueGapCurve::solvedRungs() const {
  return static_cast<int>(std::count_if(rungs_.begin(), rungs_.end(), [](const Rung& r) { return r.solved; }));
}

NormalResponse TrueGapCurve::at(double overlap) {
  if (!(overlap > 0.0)) return {.acting = false};
  NormalResponse hertz;
  if (weight_ < 1.0) {
    HertzLaw::History none;
    hertz = HertzLaw{}.force(hertz_, overlap, none);
    if (weight_ == 0.0) return hertz;
  }
  const int k = segment(overlap);
  const Rung &low = rung(k), &high = rung(k + 1);
  const double s = overlap / rungOverlap(k), m = std::log2(high.force / low.force), force = low.force * std::pow(s, m);
  const double area = low.area * std::pow(s, std::log2(high.area / low.area));
  const double w = weight_;
  return {.force = (1.0 - w) * hertz.force + w * force,
          .stiffness = (1.0 - w) * hertz.stiffness + w * m * force / overlap,
          .area = (1.0 - w) * hertz.area + w * area};
}

double TrueGapCurve::energy(double overlap) {
  if (!(overlap > 0.0)) return 0.0;
  double hertz = 0.0;
  if (weight_ < 1.0) {
    HertzLaw::History none;
    hertz = 0.4 * HertzLaw{}.force(hertz_, overlap, none).force * overlap;  // 2/5 F delta (hertz_law.hpp)
    if (weight_ == 0.0) return hertz;
  }
  // The integral of the segments' power laws from 0: F_k delta_k / (m + 1) [s^(m + 1) - 1] on each.
  const int top = segment(overlap);
  double sum = 0.0;
  for (int k = lowestRung; k <= top; ++k) {
    const Rung &low = rung(k), &high = rung(k + 1);
    const double m = std::log2(high.force / low.force), start = rungOverlap(k);
    const double end = k == top ? overlap : rungOverlap(k + 1), from = k == lowestRung ? 0.0 : 1.0;
    sum += low.force * start / (m + 1.0) * (std::pow(end / start, m + 1.0) - from);
  }
  return (1.0 - weight_) * hertz + weight_ * sum;
}

}  // namespace sqdem
