#pragma once
// Conjugate gradients with a diagonal (Jacobi) preconditioner for A x = b, A symmetric positive definite (Hestenes &
// Stiefel 1952; preconditioned as in Saad 2003, "Iterative Methods for Sparse Linear Systems", Algorithm 9.1), the
// iteration of Eigen's ConjugateGradient with its stopping rule (|r| <= tolerance |b|), written over two callbacks: the
// product y = A p, and the dot product. The dot products are exact sums rounded once (parallel_exact_sum,
// fluid/exact_sum.hpp), so every iterate is the same to the bit however the rows are split among threads (and, combined
// across processes, among processes): the solve's result does not depend on the split (DESIGN.md, "One domain seam").
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "fluid/parallel.hpp"

namespace slide {

struct ConjugateGradientReport {
  int iterations = 0;
  double error = 0.0;  // |b - A x| / |b| at the end (0 for b = 0)
  bool converged = true;
};

// Solves A x = b from the guess in x (n = b.size() rows). product(p, y) sets y = A p; inverse_diagonal holds 1 / A_rr
// (1 where A_rr is 0, as Eigen's DiagonalPreconditioner).
// combine(sums, count): several processes, each holding some of the rows: makes each of the `count` dot products'
// exact partial sums the sum over every process's (Domain::combine); every process then takes the same steps. An
// iteration combines twice: p.q, then r.r and r.z together (z is made before r.r is tested; on the last iteration it
// is not used), as each combine is a reduction every process waits for.
template <class Product, class Combine>
ConjugateGradientReport conjugate_gradient(Product&& product, const std::vector<double>& inverse_diagonal,
                                           const std::vector<double>& b, std::vector<double>& x, double tolerance,
                                           int max_iterations, Combine&& combine) {
  const std::size_t n = b.size();
  auto partial = [n](const std::vector<double>& u, const std::vector<double>& v) {
    return parallel_exact_sum_unrounded(n, [&](std::size_t i) { return u[i] * v[i]; });
  };
  auto dot = [&](const std::vector<double>& u, const std::vector<double>& v) {
    ExactSum sum = partial(u, v);
    combine(&sum, std::size_t{1});
    return sum.value();
  };
  // r.r and r.z in one combine.
  auto dots_of_r = [&](const std::vector<double>& r, const std::vector<double>& z) {
    ExactSum sums[2] = {partial(r, r), partial(r, z)};
    combine(sums, std::size_t{2});
    return std::pair{sums[0].value(), sums[1].value()};
  };
  ConjugateGradientReport report;
  const double b_norm2 = dot(b, b);
  if (b_norm2 == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    return report;
  }
  const double threshold = std::max(tolerance * tolerance * b_norm2, std::numeric_limits<double>::min());
  std::vector<double> r(n), z(n), p(n), q(n);
  product(x, q);
  parallel_for(n, [&](std::size_t i) {
    r[i] = b[i] - q[i];
    z[i] = inverse_diagonal[i] * r[i];
  });
  auto [r_norm2, rz] = dots_of_r(r, z);
  if (r_norm2 < threshold) {
    report.error = std::sqrt(r_norm2 / b_norm2);
    return report;
  }
  p = z;
  int k = 0;
  while (k < max_iterations) {
    product(p, q);
    const double alpha = rz / dot(p, q);
    parallel_for(n, [&](std::size_t i) {
      x[i] += alpha * p[i];
      r[i] -= alpha * q[i];
      z[i] = inverse_diagonal[i] * r[i];
    });
    const double rz_old = rz;
    std::tie(r_norm2, rz) = dots_of_r(r, z);
    if (r_norm2 < threshold) break;
    const double beta = rz / rz_old;
    parallel_for(n, [&](std::size_t i) { p[i] = z[i] + beta * p[i]; });
    ++k;
  }
  report.iterations = k;
  report.error = std::sqrt(r_norm2 / b_norm2);
  report.converged = report.error <= tolerance;
  return report;
}

// One process: all the rows.
template <class Product>
ConjugateGradientReport conjugate_gradient(Product&& product, const std::vector<double>& inverse_diagonal,
                                           const std::vector<double>& b, std::vector<double>& x, double tolerance,
                                           int max_iterations) {
  return conjugate_gradient(std::forward<Product>(product), inverse_diagonal, b, x, tolerance, max_iterations,
                            [](ExactSum*, std::size_t) {});
}

}  // namespace slide
