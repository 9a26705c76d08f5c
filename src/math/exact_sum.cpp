#include "sqdem/math/exact_sum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sqdem {
namespace {

using Limbs = std::array<std::int64_t, ExactSum::limbCount>;
__extension__ using Wide = unsigned __int128;  // GCC's and Clang's 128-bit integer

/// The carries of limbs [lo, hi) moved up, and on while one is left: every limb a balanced digit
/// in [-2^31, 2^31) (the sum's sign is its top non-zero digit's). Returns the end of the limbs
/// that may now be non-zero.
int propagateCarries(Limbs& limb, int lo, int hi) {
  std::int64_t carry = 0;
  int c = lo;
  for (; c < ExactSum::limbCount && (c < hi || carry != 0); ++c) {
    const std::int64_t v = limb[c] + carry;
    carry = (v + (std::int64_t{1} << 31)) >> 32;  // floor division: the digit left is balanced
    limb[c] = v - carry * (std::int64_t{1} << 32);
  }
  return c;  // a carry out of the top limb would need a sum beyond 2^1100: none of doubles
}

}  // namespace

void ExactSum::normalise() {
  if (lo_ < hi_) hi_ = propagateCarries(limb_, lo_, hi_);
  pending_ = 0;
}

ExactSum& ExactSum::operator+=(const ExactSum& other) {
  nonFinite_ += other.nonFinite_;
  if (other.lo_ >= other.hi_) return *this;
  if (pending_ > carryEvery - 1 - other.pending_) normalise();
  if (pending_ > carryEvery - 1 - other.pending_) {  // other at its full count: its propagated form
    const Limbs theirs = other.limbs();
    for (int c = 0; c < limbCount; ++c) limb_[c] += theirs[c];
    hi_ = limbCount;
    pending_ += 1;  // balanced digits: within one addition's worth
  } else {
    for (int c = other.lo_; c < other.hi_; ++c) limb_[c] += other.limb_[c];
    hi_ = std::max(hi_, other.hi_);
    pending_ += other.pending_ + 1;
  }
  lo_ = std::min(lo_, other.lo_);
  return *this;
}

void ExactSum::clear() {
  if (lo_ < hi_) std::fill(limb_.begin() + lo_, limb_.begin() + hi_, 0);
  nonFinite_ = 0.0;
  pending_ = 0;
  lo_ = limbCount;
  hi_ = 0;
}

std::array<std::int64_t, ExactSum::limbCount> ExactSum::limbs() const {
  Limbs limb = limb_;
  if (lo_ < hi_) propagateCarries(limb, lo_, hi_);
  return limb;
}

ExactSum ExactSum::fromLimbs(std::span<const std::int64_t, limbCount> limbs, double nonFinite) {
  ExactSum s;
  std::copy(limbs.begin(), limbs.end(), s.limb_.begin());
  s.nonFinite_ = nonFinite;
  s.pending_ = carryEvery;  // a sum of many ranks' digits: propagate before the next addition
  for (int c = 0; c < limbCount; ++c) {
    if (limbs[c] != 0) {
      s.lo_ = std::min(s.lo_, c);
      s.hi_ = c + 1;
    }
  }
  return s;
}

double ExactSum::value() const {
  if (std::isnan(nonFinite_)) return std::numeric_limits<double>::quiet_NaN();
  if (nonFinite_ != 0.0) return nonFinite_;
  if (lo_ >= hi_) return 0.0;
  Limbs limb = limb_;
  int top = propagateCarries(limb, lo_, hi_) - 1;
  while (top >= lo_ && limb[top] == 0) --top;
  if (top < lo_) return 0.0;
  // The magnitude in digits [0, 2^32) (floor carries: the top digit stays positive).
  const bool negative = limb[top] < 0;
  for (int c = lo_; c < top; ++c) {
    const std::int64_t d = negative ? -limb[c] : limb[c];
    const std::int64_t carry = d >> 32;
    limb[c] = d - carry * (std::int64_t{1} << 32);
    limb[c + 1] += negative ? -carry : carry;
  }
  if (negative) limb[top] = -limb[top];
  while (limb[top] == 0) --top;  // a borrow may have emptied the top digit (not the lowest: the sum is not 0)
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
