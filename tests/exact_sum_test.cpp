// ExactSum (math/exact_sum.hpp) against an exact integer reference: every double is an integer
// multiple of 2^-1074, so the sum times 2^1074 is an integer (Boost.Multiprecision's cpp_int),
// rounded here to the nearest double, ties to even (IEEE 754-2019, 4.3.1), by integer arithmetic
// independent of the accumulator's limbs.

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sqdem/math/exact_sum.hpp"

namespace sqdem {
namespace {

using boost::multiprecision::cpp_int;

cpp_int scaled(double x) {  // x 2^1074, exactly
  int e = 0;
  const double m = std::frexp(std::abs(x), &e);
  cpp_int v = static_cast<long long>(std::ldexp(m, 53));
  const int s = e + 1074 - 53;
  v = s >= 0 ? cpp_int(v << s) : cpp_int(v >> -s);  // the bits shifted out are zero (subnormals)
  return x < 0 ? cpp_int(-v) : v;
}

double rounded(const cpp_int& total) {
  const bool negative = total < 0;
  const cpp_int a = negative ? cpp_int(-total) : total;
  if (a == 0) return 0.0;
  const int bits = static_cast<int>(boost::multiprecision::msb(a)) + 1;
  const int shift = std::max(bits - 53, 0);
  cpp_int mantissa = a >> shift;
  if (shift > 0) {
    const cpp_int rest = a - (mantissa << shift), half = cpp_int(1) << (shift - 1);
    if (rest > half || (rest == half && (mantissa & 1) != 0)) ++mantissa;
  }
  const double v = std::ldexp(mantissa.convert_to<double>(), shift - 1074);
  return negative ? -v : v;
}

double reference(const std::vector<double>& xs) {
  cpp_int total = 0;
  for (double x : xs) total += scaled(x);
  return rounded(total);
}

double exact(const std::vector<double>& xs) {
  ExactSum s;
  for (double x : xs) s.add(x);
  return s.value();
}

/// Doubles of every magnitude, subnormals included, both signs.
std::vector<double> wildAddends(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-1074, 1000);
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    xs.push_back(rng() % 2 ? x : -x);
  }
  return xs;
}

TEST(ExactSum, MatchesTheExactIntegerSumRoundedOnce) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> xs = wildAddends(rng, 1 + trial % 50);
    // Cancellation down to the small terms: the large ones again with the other sign.
    if (trial % 2) {
      const std::size_t n = xs.size();
      for (std::size_t i = 0; i < n; ++i) {
        if (std::abs(xs[i]) > 1e-300) xs.push_back(-xs[i]);
      }
    }
    EXPECT_EQ(exact(xs), reference(xs)) << "trial " << trial;
  }
}

TEST(ExactSum, SameBitsInAnyOrderAndAnySplit) {
  std::mt19937_64 rng(11);
  std::vector<double> xs = wildAddends(rng, 3000);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 3000; ++i) xs.push_back(unit(rng));  // ordinary values that round-off would mix
  const double once = exact(xs);
  EXPECT_EQ(once, reference(xs));
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(xs.begin(), xs.end(), rng);
    EXPECT_EQ(exact(xs), once);
    // Split as three threads' shares merged, and as three ranks' limbs added limb-wise.
    std::array<ExactSum, 3> parts;
    for (std::size_t i = 0; i < xs.size(); ++i) parts[i % 3].add(xs[i]);
    ExactSum merged = parts[0];
    merged += parts[1];
    merged += parts[2];
    EXPECT_EQ(merged.value(), once);
    std::array<std::int64_t, ExactSum::limbCount> total{};
    for (const ExactSum& p : parts) {
      const auto limbs = p.limbs();
      for (int c = 0; c < ExactSum::limbCount; ++c) total[c] += limbs[c];
    }
    EXPECT_EQ(ExactSum::fromLimbs(total, 0.0).value(), once);
  }
}

TEST(ExactSum, RoundsToNearestTiesToEven) {
  const double ulpHalf = std::ldexp(1.0, -53);  // half an ulp of 1
  EXPECT_EQ(exact({1.0, ulpHalf}), 1.0);                                // tie, even stays
  EXPECT_EQ(exact({1.0 + 2 * ulpHalf, ulpHalf}), 1.0 + 4 * ulpHalf);    // tie, odd rounds up
  EXPECT_EQ(exact({1.0, ulpHalf, std::ldexp(1.0, -1074)}), 1.0 + 2 * ulpHalf);  // past the tie
  EXPECT_EQ(exact({1e308, 1.0, -1e308}), 1.0);
  EXPECT_EQ(exact({0.1, 0.2, -0.3}), reference({0.1, 0.2, -0.3}));
  EXPECT_EQ(exact({std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::denorm_min()}),
            2 * std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(exact({}), 0.0);
  EXPECT_EQ(exact({2.5, -2.5}), 0.0);
}

TEST(ExactSum, OverflowAndNonFiniteAddendsFollowIeee) {
  EXPECT_EQ(exact({DBL_MAX, DBL_MAX}), HUGE_VAL);
  EXPECT_EQ(exact({-DBL_MAX, -DBL_MAX}), -HUGE_VAL);
  EXPECT_EQ(exact({DBL_MAX, DBL_MAX, -DBL_MAX}), DBL_MAX);  // the intermediate overflow is not lost
  EXPECT_EQ(exact({HUGE_VAL, 1.0}), HUGE_VAL);
  EXPECT_TRUE(std::isnan(exact({HUGE_VAL, -HUGE_VAL})));
  EXPECT_TRUE(std::isnan(exact({1.0, std::numeric_limits<double>::quiet_NaN()})));
}

TEST(ExactSum, CarriesAfterManyAdditions) {
  // More additions than a limb takes without a carry (2^30): 1.5 and 2^40 + 0.5 land in the
  // same limbs every time.
  ExactSum s;
  const long long n = (1LL << 30) + 12345;
  for (long long i = 0; i < n; ++i) s.add(i % 2 ? 1.5 : 1099511627776.5);
  const long long pairs = n / 2;
  const double evens = static_cast<double>(n - pairs), odds = static_cast<double>(pairs);
  EXPECT_EQ(s.value(), reference({evens * 1099511627776.0, odds * 1.5 + evens * 0.5}));  // each term exact
}

TEST(ExactSum, MergesOfMergesAndRankFormsStayExact) {
  // A step's wall loads: threads' shares of addends in a narrow range of one sign (a negative
  // total), merged into a running sum again and again, with rank forms (limbs, fromLimbs) mixed
  // in: the merged count of pending additions must force the carries in time.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> load(-2e-3, 5e-4);
  std::vector<double> all;
  ExactSum running;
  for (int round = 0; round < 300; ++round) {
    std::array<ExactSum, 2> shares;
    for (int i = 0; i < 40; ++i) {
      const double x = load(rng);
      all.push_back(x);
      shares[i % 2].add(x);
    }
    running += shares[0];
    running += round % 3 == 0 ? ExactSum::fromLimbs(shares[1].limbs(), 0.0) : shares[1];
    if (round % 50 == 0) running = ExactSum::fromLimbs(running.limbs(), 0.0);
  }
  EXPECT_LT(running.value(), 0.0);
  EXPECT_EQ(running.value(), reference(all));
  ExactSum negated;
  for (double x : all) negated.add(-x);
  EXPECT_EQ(negated.value(), -reference(all));
}

}  // namespace
}  // namespace sqdem
