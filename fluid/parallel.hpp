#pragma once
// The one place where loops run in parallel. Physics code calls these helpers and never holds a pragma.
// Every helper gives results that do not depend on the number of threads: each index is handled by exactly one
// thread, and reductions are either order-independent (max/min) or done serially over per-index values.
#include <omp.h>

#include <array>
#include <cstddef>

#include "fluid/exact_sum.hpp"

namespace slide {

// Loops shorter than this run on one thread: starting a parallel region costs more than they do, and threads that
// spin waiting for work slow everything down when the machine is busy with other jobs.
inline constexpr long parallel_threshold = 4096;
// Threads take chunks of this many indices as they finish: particles are in cell order, and a static split gave one
// thread the walls (which most stages skip) and the other the water, so one waited for the other (libgomp's wait was
// 10 % of the bench case on 2 threads, perf). Which thread computes an index never changes its result.
inline constexpr long parallel_chunk = 512;

template <class F>
void parallel_for(std::size_t n, F&& f) {
#pragma omp parallel for schedule(dynamic, parallel_chunk) if (static_cast<long>(n) >= parallel_threshold)
  for (long i = 0; i < static_cast<long>(n); ++i) f(static_cast<std::size_t>(i));
}

// f(b) for b = 0 .. blocks - 1, one block to a thread at a time, in parallel when the `items` the blocks hold are many.
template <class F>
void parallel_for_blocks(std::size_t blocks, std::size_t items, F&& f) {
#pragma omp parallel for schedule(dynamic, 1) if (static_cast<long>(items) >= parallel_threshold)
  for (long b = 0; b < static_cast<long>(blocks); ++b) f(static_cast<std::size_t>(b));
}

// max over i of f(i), starting from init. Max is exact and associative, so the thread split does not matter.
template <class F>
double parallel_max(std::size_t n, double init, F&& f) {
  double result = init;
#pragma omp parallel for schedule(dynamic, parallel_chunk) reduction(max : result) if (static_cast<long>(n) >= parallel_threshold)
  for (long i = 0; i < static_cast<long>(n); ++i) {
    const double v = f(static_cast<std::size_t>(i));
    if (v > result) result = v;
  }
  return result;
}

// The same for several maxima at once (component k of f(i) into component k of the result): one pass over the
// particles where each maximum had its own.
template <std::size_t K, class F>
std::array<double, K> parallel_max_each(std::size_t n, const std::array<double, K>& init, F&& f) {
  std::array<double, K> result = init;
#pragma omp parallel if (static_cast<long>(n) >= parallel_threshold)
  {
    std::array<double, K> local = init;
#pragma omp for schedule(dynamic, parallel_chunk) nowait
    for (long i = 0; i < static_cast<long>(n); ++i) {
      const std::array<double, K> v = f(static_cast<std::size_t>(i));
      for (std::size_t k = 0; k < K; ++k)
        if (v[k] > local[k]) local[k] = v[k];
    }
#pragma omp critical(slide_parallel_max_each)
    for (std::size_t k = 0; k < K; ++k)
      if (local[k] > result[k]) result[k] = local[k];
  }
  return result;
}

// The sum over i of f(i), exact (fluid/exact_sum.hpp): each thread sums its indices into its own accumulator and the
// accumulators are added, which is exact too, so the result does not depend on the split.
template <class F>
ExactSum parallel_exact_sum_unrounded(std::size_t n, F&& f) {
  ExactSum total;
#pragma omp parallel if (static_cast<long>(n) >= parallel_threshold)
  {
    ExactSum local;
#pragma omp for schedule(dynamic, parallel_chunk) nowait
    for (long i = 0; i < static_cast<long>(n); ++i) local.add(f(static_cast<std::size_t>(i)));
#pragma omp critical(slide_parallel_exact_sum)
    total += local;
  }
  return total;
}

// The same, rounded once.
template <class F>
double parallel_exact_sum(std::size_t n, F&& f) {
  return parallel_exact_sum_unrounded(n, std::forward<F>(f)).value();
}

inline int thread_count() { return omp_get_max_threads(); }
inline void set_thread_count(int n) { omp_set_num_threads(n); }

}  // namespace slide
