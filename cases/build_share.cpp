#include "cases/build_share.hpp"

#include <cmath>
#include <limits>

namespace slide::cases {

long column_of(const Vec<3>& x, int axis, double dp) { return static_cast<long>(std::floor(x[axis] / dp)); }

void BuildCount::add(const Vec<3>& x, double dp) {
  for (int a = 0; a < 2; ++a) ++per_column[a][column_of(x, a, dp)];
  lo = lo.cwiseMin(x);
  hi = hi.cwiseMax(x);
  ++particles;
}

BuildShare::BuildShare(const BuildCount& count, double dp, long margin_columns, int processes, int rank)
    : dp_(dp), margin_(margin_columns) {
  // The axis of the wider spread in columns (x where they tie).
  const auto spread = [&](int a) {
    const auto& m = count.per_column[a];
    return m.empty() ? 0L : m.rbegin()->first - m.begin()->first;
  };
  axis_ = spread(1) > spread(0) ? 1 : 0;
  // Process r's slab begins at the first column before which r / processes of the particles lie; the first's reaches
  // down to any column, the last's up.
  const std::int64_t total = count.particles;
  const auto& columns = count.per_column[axis_];
  first_ = std::numeric_limits<long>::min() / 2;  // (room for the margin either side)
  end_ = std::numeric_limits<long>::max() / 2;
  std::int64_t before = 0;
  bool first_set = rank == 0, end_set = rank + 1 == processes;
  for (const auto& [column, n] : columns) {
    if (!first_set && before * processes >= std::int64_t(rank) * total) first_ = column, first_set = true;
    if (!end_set && before * processes >= std::int64_t(rank + 1) * total) end_ = column, end_set = true;
    before += n;
  }
  if (!first_set) first_ = end_;  // (a slab past the last column: empty)
  for (const auto& [column, n] : columns) {
    if (column >= first_ - margin_ && column < end_ + margin_) held_ += n;
    if (column >= first_ && column < end_) owned_ += n;
  }
}

}  // namespace slide::cases
