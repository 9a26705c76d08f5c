#include "sqdem/math/exact_sum.hpp"

#include <algorithm>
#include <cmath>

namespace sqdem {
namespace {

using Limbs = std::array<std::int64_t, ExactSum::limbCount>;
__extension__ using Wide = unsigned __int128;  // GCC's and Clang's 128-bit integer

/// Every limb below the top one brought into [0, 2^32), its carry moved up.
void propagateCarries(Limbs& limb) {
  for (int c = 0; c + 1 < ExactSum::limbCount; ++c) {
    const std::int64_t carry = limb[c] >> 32;  // floor division: the digit left is in [0, 2^32)
    limb[c] -= carry * (std::int64_t{1} << 32);
    limb[c + 1] += carry;
  }
}

}  // namespace

void ExactSum::normalise() {
  propagateCarries(limb_);
  pending_ = 0;
}

ExactSum& ExactSum::operator+=(const ExactSum& other) {
  normalise();
  const Limbs theirs = other.limbs();
  for (int c = 0; c < limbCount; ++c) limb_[c] += theirs[c];
  pending_ = 2;  // each digit now below 2^33: two additions' worth
  nonFinite_ += other.nonFinite_;
  return *this;
}

std::array<std::int64_t, ExactSum::limbCount> ExactSum::limbs() const {
  Limbs limb = limb_;
  propagateCarries(limb);
  return limb;
}

ExactSum ExactSum::fromLimbs(std::span<const std::int64_t, limbCount> limbs, double nonFinite) {
  ExactSum s;
  std::copy(limbs.begin(), limbs.end(), s.limb_.begin());
  s.nonFinite_ = nonFinite;
  s.pending_ = carryEvery;  // a sum of many ranks' digits: propagate before the next addition
  return s;
}

double ExactSum::value() const {
  if (nonFinite_ != 0.0 || std::isnan(nonFinite_)) return nonFinite_;
  Limbs limb = limbs();
  const bool negative = limb[limbCount - 1] < 0;
  if (negative) {
    for (std::int64_t& d : limb) d = -d;
    propagateCarries(limb);
  }
  int top = limbCount - 1;
  while (top >= 0 && limb[top] == 0) --top;
  if (top < 0) return 0.0;
  // The largest double is below 2^1024, bit 2098 of the accumulator, in limb 65.
  if (top > 65) return negative ? -HUGE_VAL : HUGE_VAL;
  // The three digits from the top one (at least 65 significant bits when the top is limb 2 or
  // higher; all digits when lower) and whether any bit below them is set.
  const int base = std::max(top, 2);
  const auto digit = [&](int c) { return static_cast<Wide>(static_cast<std::uint64_t>(limb[c])); };
  const Wide m = (digit(base) << 64) | (digit(base - 1) << 32) | digit(base - 2);
  const bool sticky = std::any_of(limb.begin(), limb.begin() + (base - 2), [](std::int64_t d) { return d != 0; });
  const auto high = static_cast<std::uint64_t>(m >> 64);
  const int bits = high != 0 ? 128 - std::countl_zero(high) : 64 - std::countl_zero(static_cast<std::uint64_t>(m));
  // 53 bits kept: the result is normal whenever rounding is needed (the top bit then sits at
  // 2^-1022 or above), so a single rounding, to nearest with ties to even.
  const int shift = std::max(bits - 53, 0);
  auto mantissa = static_cast<std::uint64_t>(m >> shift);
  if (shift > 0) {
    const Wide rest = m & ((static_cast<Wide>(1) << shift) - 1);
    const Wide half = static_cast<Wide>(1) << (shift - 1);
    if (rest > half || (rest == half && (sticky || (mantissa & 1) != 0))) ++mantissa;
  }
  const double magnitude = std::ldexp(static_cast<double>(mantissa), 32 * (base - 2) + shift - 1074);
  return negative ? -magnitude : magnitude;
}

}  // namespace sqdem
