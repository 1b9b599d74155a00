// The order-free sum (fluid/exact_sum.hpp) against exact answers: sums whose exact value is known, rounded once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "fluid/exact_sum.hpp"

namespace slide {
namespace {

double sum_of(const std::vector<double>& terms) {
  ExactSum s;
  for (const double t : terms) s.add(t);
  return s.value();
}

TEST(ExactSum, CancellationLeavesTheSmallTermExactly) {
  EXPECT_EQ(sum_of({1e100, 1.0, -1e100}), 1.0);
  // The three doubles nearest 0.1, 0.2 and 0.3 sum to 2^-55 exactly; the running sum gives 2^-54.
  EXPECT_EQ(sum_of({0.1, 0.2, -0.3}), std::ldexp(1.0, -55));
  EXPECT_EQ((0.1 + 0.2) - 0.3, std::ldexp(1.0, -54));
  EXPECT_EQ(sum_of({}), 0.0);
  EXPECT_EQ(sum_of({3.5, -3.5}), 0.0);
  EXPECT_EQ(sum_of({-2.25}), -2.25);
}

// The double range's ends: subnormals add exactly, and a sum passing beyond the largest double comes back.
TEST(ExactSum, SubnormalAndHugeTerms) {
  const double tiny = std::ldexp(1.0, -1074);
  EXPECT_EQ(sum_of({tiny, tiny}), std::ldexp(1.0, -1073));
  EXPECT_EQ(sum_of({DBL_MIN, -tiny}), DBL_MIN - tiny);
  EXPECT_EQ(sum_of({DBL_MAX, DBL_MAX, -DBL_MAX}), DBL_MAX);
  EXPECT_EQ(sum_of({-DBL_MAX, -DBL_MAX, DBL_MAX, tiny}), -DBL_MAX);
  EXPECT_EQ(sum_of({DBL_MAX, tiny, -DBL_MAX}), tiny);
}

// Rounded once, to nearest with ties to even: 2^53 + 1 is a tie (to 2^53), anything above it goes up.
TEST(ExactSum, RoundsOnceToNearestEven) {
  const double two53 = std::ldexp(1.0, 53);
  EXPECT_EQ(sum_of({two53, 1.0}), two53);
  EXPECT_EQ(sum_of({two53, 1.0, std::ldexp(1.0, -60)}), two53 + 2.0);
  EXPECT_EQ(sum_of({two53, 3.0}), two53 + 4.0);
  EXPECT_EQ(sum_of({-two53, -1.0, -std::ldexp(1.0, -900)}), -(two53 + 2.0));
}

// Random terms that are multiples of 2^-40 below 2^12: their exact sum is an integer count of 2^-40 (kept in 128 bits),
// and the result is that count rounded once, whatever the order and however the terms are split into partial sums.
TEST(ExactSum, AnyOrderAndAnySplitGiveTheExactSumRoundedOnce) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> units(-(std::int64_t{1} << 52), std::int64_t{1} << 52);
  std::vector<double> terms;
  __int128 exact = 0;
  for (int k = 0; k < 20000; ++k) {
    const std::int64_t u = units(rng);
    exact += u;
    terms.push_back(std::ldexp(static_cast<double>(u), -40));  // exact: |u| <= 2^52
  }
  const double expected = std::ldexp(static_cast<double>(exact), -40);  // one rounding (int128 to double)
  EXPECT_EQ(sum_of(terms), expected);
  for (int trial = 0; trial < 3; ++trial) {
    std::shuffle(terms.begin(), terms.end(), rng);
    const std::size_t cut = terms.size() * (trial + 1) / 5;
    ExactSum a, b;
    for (std::size_t k = 0; k < terms.size(); ++k) (k < cut ? a : b).add(terms[k]);
    b += a;
    EXPECT_EQ(b.value(), expected);
    // As a process would receive another's partial sum: its digits.
    ExactSum c = ExactSum::from_digits(a.normalised_digits());
    ExactSum d;
    for (std::size_t k = cut; k < terms.size(); ++k) d.add(terms[k]);
    c += d;
    EXPECT_EQ(c.value(), expected);
  }
  // The plain running sum of these terms rounds at every step and does depend on the order.
  double plain = 0.0;
  for (const double t : terms) plain += t;
  EXPECT_NEAR(plain, expected, 1e-6 * std::abs(expected) + 1e-3);
}

TEST(ExactSum, ATermThatIsNotFiniteIsRefused) {
  ExactSum s;
  EXPECT_THROW(s.add(std::nan("")), std::domain_error);
  EXPECT_THROW(s.add(INFINITY), std::domain_error);
}

}  // namespace
}  // namespace slide
