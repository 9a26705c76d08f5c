#pragma once
// An exact sum of doubles: Kulisch's long accumulator (U. Kulisch, "Computer Arithmetic and
// Validity", de Gruyter 2013, ch. 8), a fixed-point number covering the whole double range
// (2^-1074 to 2^1024) in 32-bit digits, each held in a signed 64-bit limb so that 2^30 additions
// need no carry. Every addend is kept to its last bit, so the sum, rounded once to the nearest
// double (ties to even), is the same whatever the order of the additions and however they are
// split between threads or ranks: the global sums of the engine (wall loads, kinetic energy,
// the energy ledger, packing measures) come out bitwise the same at any decomposition
// (docs/architecture.md, "Reductions"). Hand-written: no Debian package offers one (ReproBLAS
// and the exact accumulators of CRlibm/MPFR-based codes are not packaged, or round-trip through
// multi-precision objects far slower than the ~2 ns an addition costs here).
//
// The accumulator keeps the range of limbs its addends touched: carries, merges and the final
// rounding visit that range only (a few limbs for the loads of one wall, not all 68), and carries
// leave balanced digits, in [-2^31, 2^31), so that a negative sum needs no chain of borrows up to
// the top limb.
//
// Non-finite addends make the sum their IEEE sum: inf, or NaN for inf - inf or any NaN (always
// the default quiet NaN, whose bits do not depend on which NaN came first).

#include <array>
#include <bit>
#include <cstdint>
#include <span>

namespace sqdem {

class ExactSum {
 public:
  /// 32-bit digits from 2^-1074 up: 2046 + 53 bits of addends and headroom for 2^64 of them.
  static constexpr int limbCount = 68;

  ExactSum() = default;

  void add(double x) {
    if (pending_ == carryEvery) normalise();
    ++pending_;
    addBits(x);
  }
  ExactSum& operator+=(double x) {
    add(x);
    return *this;
  }
  /// Adds another sum (a thread's or a rank's share).
  ExactSum& operator+=(const ExactSum& other);
  /// Back to zero (the limbs touched only: cheaper than a fresh accumulator).
  void clear();

  /// The sum rounded to the nearest double, ties to even (inf when it exceeds the range).
  double value() const;

  /// The limbs with every carry propagated (each a balanced digit, in [-2^31, 2^31)) and the
  /// non-finite part: the form a rank sends, whose limb-wise integer sum over ranks is the sum
  /// of the ranks' sums (fromLimbs). Sums of up to 2^31 such forms cannot overflow a limb.
  std::array<std::int64_t, limbCount> limbs() const;
  double nonFinite() const { return nonFinite_; }
  static ExactSum fromLimbs(std::span<const std::int64_t, limbCount> limbs, double nonFinite);

 private:
  static constexpr int carryEvery = 1 << 30;
  void addBits(double x);
  void normalise();

  /// Every limb below (pending_ + 1) 2^32 in magnitude: pending_ counts additions since the
  /// last carry propagation (a merged sum, its own and one more for its digits).
  std::array<std::int64_t, limbCount> limb_{};
  double nonFinite_ = 0.0;  ///< the IEEE sum of the inf and NaN addends
  int pending_ = 0;
  int lo_ = limbCount, hi_ = 0;  ///< the limbs outside [lo_, hi_) are zero
};

inline void ExactSum::addBits(double x) {
  // x = +-m 2^(e - 1075) for a biased exponent e >= 1 (m with its hidden bit), +-m 2^-1074 for
  // e = 0: its lowest bit sits at bit p = max(e - 1, 0) of the accumulator.
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const auto exponent = static_cast<int>((bits >> 52) & 0x7ff);
  if (exponent == 0x7ff) {
    nonFinite_ += x;
    return;
  }
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t mantissa = exponent == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  if (mantissa == 0) return;  // a zero adds nothing (and widens no range)
  const int p = exponent == 0 ? 0 : exponent - 1;
  const int offset = p & 31, c = p >> 5;
  const std::uint64_t low = mantissa << offset, high = offset == 0 ? 0 : mantissa >> (64 - offset);  // < 2^84
  const std::int64_t sign = (bits >> 63) != 0 ? -1 : 1;
  lo_ = c < lo_ ? c : lo_;
  hi_ = c + 3 > hi_ ? c + 3 : hi_;
  limb_[c] += sign * static_cast<std::int64_t>(low & 0xffffffffu);
  limb_[c + 1] += sign * static_cast<std::int64_t>(low >> 32);
  limb_[c + 2] += sign * static_cast<std::int64_t>(high);
}

}  // namespace sqdem
