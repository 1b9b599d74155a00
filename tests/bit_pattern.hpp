#pragma once
// A double's bit pattern, for tests that ask for bit-identical results (it tells +0 from -0, and NaNs apart).
#include <bit>
#include <cstdint>

namespace slide::testing {

inline std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

}  // namespace slide::testing
