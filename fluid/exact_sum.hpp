#pragma once
// A sum of doubles that does not depend on the order of its terms (DESIGN.md, "One domain seam"): every term is added
// exactly into a fixed-point number wide enough for any double (a long accumulator, after Kulisch), and only the
// total is rounded to a double. Whatever order threads or processes add the terms in, and however they are split
// into partial sums, value() is the same to the bit: sums over particles (a body's force, the conjugate gradient's
// dot products) give the same result for any thread and process count.
//
// The number is held as signed 32-bit digits in 64-bit words: value = sum_k digit[k] 2^(32 k - bias). A term adds to
// three digits without carrying; carries are pushed up (normalise) before the words could overflow and before reading.
// Cost, measured in tests/test_exact_sum.cpp's neighbour: a few nanoseconds a term.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "fluid/communicator.hpp"

namespace slide {

class ExactSum {
 public:
  // Digits cover 2^-1074 (the least subnormal) to 2^1230, headroom above 2^1024 for the carries of any number of
  // terms.
  static constexpr int digit_count = 72;
  static constexpr int bias = 1074;  // bit position of 2^0

  ExactSum() = default;
  explicit ExactSum(double x) { add(x); }

  // Adds x exactly. Throws std::domain_error for a value that is not finite (a sum of it has no exact value; the
  // caller's checks report where it came from).
  void add(double x) {
    if (x == 0.0) return;
    if (!std::isfinite(x)) throw std::domain_error("ExactSum: a term that is not finite");
    // x = mantissa 2^(p - bias) from its IEEE 754 fields: exponent field f gives a unit of 2^(f - 1075) for a normal
    // number (implicit leading bit), 2^-1074 for a subnormal one.
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int field = static_cast<int>(bits >> 52 & 0x7ff);
    std::int64_t mantissa = static_cast<std::int64_t>(bits & ((std::uint64_t{1} << 52) - 1));
    if (field != 0) mantissa |= std::int64_t{1} << 52;
    if (bits >> 63) mantissa = -mantissa;
    const int p = field == 0 ? 0 : field - 1;  // the unit's bit position, bias = 1074
    const int k = p / 32, s = p % 32;
    const __int128 v = static_cast<__int128>(mantissa) * (static_cast<__int128>(1) << s);
    digit_[k] += static_cast<std::int64_t>(v & 0xffffffff);
    digit_[k + 1] += static_cast<std::int64_t>((v >> 32) & 0xffffffff);
    digit_[k + 2] += static_cast<std::int64_t>(v >> 64);  // arithmetic: the sign
    if (++pending_ == max_pending) normalise();
  }

  ExactSum& operator+=(double x) {
    add(x);
    return *this;
  }
  ExactSum& operator+=(const ExactSum& other) {
    ExactSum b = other;
    b.normalise();
    normalise();
    for (int k = 0; k < digit_count; ++k) digit_[k] += b.digit_[k];
    pending_ = 1;
    normalise();
    return *this;
  }

  // The sum, rounded to the nearest double (ties to even; below the normal range it may round twice). The same bits
  // for the same terms in any order.
  double value() const {
    ExactSum a = *this;
    a.normalise();
    const bool negative = a.digit_[digit_count - 1] < 0;
    if (negative) a.negate();
    int h = digit_count - 1;
    while (h >= 0 && a.digit_[h] == 0) --h;
    if (h < 0) return 0.0;
    if (h < 2) h = 2;  // a tiny sum: its digits all fit in the three read below
    using U = unsigned __int128;
    U top = (static_cast<U>(a.digit_[h]) << 64) | (static_cast<U>(a.digit_[h - 1]) << 32) |
            static_cast<U>(a.digit_[h - 2]);
    bool sticky = false;
    for (int k = 0; k < h - 2; ++k) sticky = sticky || a.digit_[k] != 0;
    // top holds at least 65 significant bits (its highest digit is not zero), so its lowest bit lies below the
    // rounding position: setting it records the digits below without changing the rounding of anything else.
    if (sticky) top |= 1;
    const double r = std::ldexp(static_cast<double>(top), 32 * (h - 2) - bias);
    return negative ? -r : r;
  }

  // The digits, carried (for combining across processes: equal sums have equal digits).
  const std::array<std::int64_t, digit_count>& normalised_digits() {
    normalise();
    return digit_;
  }
  static ExactSum from_digits(const std::array<std::int64_t, digit_count>& digits) {
    ExactSum s;
    s.digit_ = digits;
    s.pending_ = 1;
    s.normalise();
    return s;
  }

 private:
  // Each add puts less than 2^32 into a word; words hold 2^63: carry well before.
  static constexpr int max_pending = 1 << 29;

  // Every digit but the highest into [0, 2^32), the highest signed: one form for each value.
  void normalise() {
    if (pending_ == 0) return;
    for (int k = 0; k + 1 < digit_count; ++k) {
      const std::int64_t carry = digit_[k] >> 32;  // floor division (arithmetic shift)
      digit_[k] -= carry * (static_cast<std::int64_t>(1) << 32);
      digit_[k + 1] += carry;
    }
    pending_ = 0;
  }
  // -value, from the normalised form, normalised.
  void negate() {
    for (auto& d : digit_) d = -d;
    pending_ = 1;
    normalise();
  }

  std::array<std::int64_t, digit_count> digit_{};
  int pending_ = 0;  // adds since the last normalise
};

// Each of the `count` exact sums becomes the sum of every process's: the digits summed as integers, exact whatever the
// split (collective).
inline void sum_across(const Communicator& comm, ExactSum* sums, std::size_t count) {
  constexpr std::size_t n = ExactSum::digit_count;
  std::vector<std::int64_t> digits(count * n);
  for (std::size_t s = 0; s < count; ++s) {
    const auto& d = sums[s].normalised_digits();
    std::copy(d.begin(), d.end(), digits.begin() + static_cast<std::ptrdiff_t>(s * n));
  }
  comm.sum(digits.data(), digits.size());
  for (std::size_t s = 0; s < count; ++s) {
    std::array<std::int64_t, n> d;
    std::copy_n(digits.begin() + static_cast<std::ptrdiff_t>(s * n), n, d.begin());
    sums[s] = ExactSum::from_digits(d);
  }
}

}  // namespace slide
