// The conjugate-gradient solve (fluid/conjugate_gradient.hpp) against exact answers: a system whose solution is known,
// the finite termination of CG (n distinct eigenvalues: n iterations), and the same bits for 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "fluid/conjugate_gradient.hpp"
#include "fluid/parallel.hpp"

namespace slide {
namespace {

// A = tridiag(-1, 2 + s_i, -1), s_i > 0 varying: symmetric, strictly diagonally dominant, positive definite.
struct Tridiagonal {
  std::vector<double> shift;
  explicit Tridiagonal(std::size_t n) : shift(n) {
    for (std::size_t i = 0; i < n; ++i) shift[i] = 0.1 + 0.05 * static_cast<double>(i % 7);
  }
  std::size_t size() const { return shift.size(); }
  double diagonal(std::size_t i) const { return 2.0 + shift[i]; }
  void product(const std::vector<double>& p, std::vector<double>& y) const {
    const std::size_t n = size();
    parallel_for(n, [&](std::size_t i) {
      double v = diagonal(i) * p[i];
      if (i > 0) v -= p[i - 1];
      if (i + 1 < n) v -= p[i + 1];
      y[i] = v;
    });
  }
};

ConjugateGradientReport solve(const Tridiagonal& A, const std::vector<double>& b, std::vector<double>& x, double tol,
                              int max_iterations) {
  std::vector<double> inverse_diagonal(A.size());
  for (std::size_t i = 0; i < A.size(); ++i) inverse_diagonal[i] = 1.0 / A.diagonal(i);
  return conjugate_gradient([&](const std::vector<double>& p, std::vector<double>& y) { A.product(p, y); },
                            inverse_diagonal, b, x, tol, max_iterations);
}

TEST(ConjugateGradient, FindsAKnownSolutionToTheTolerance) {
  const Tridiagonal A(200);
  std::vector<double> exact(A.size()), b(A.size()), x(A.size(), 0.0);
  for (std::size_t i = 0; i < A.size(); ++i) exact[i] = std::sin(0.1 * static_cast<double>(i)) + 0.01 * static_cast<double>(i);
  A.product(exact, b);
  const ConjugateGradientReport r = solve(A, b, x, 1e-12, 500);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.error, 1e-12);
  EXPECT_GT(r.iterations, 5);
  // The residual bound and A's condition number (< (4.4 / 0.1) = 44) bound the error: |x - exact| <= 44e-12 |exact|.
  double e2 = 0.0, x2 = 0.0;
  for (std::size_t i = 0; i < A.size(); ++i) e2 += (x[i] - exact[i]) * (x[i] - exact[i]), x2 += exact[i] * exact[i];
  EXPECT_LT(std::sqrt(e2 / x2), 44e-12);
}

// A 2 x 2 system: CG ends in two steps (its residuals are A-orthogonal), here to round-off.
TEST(ConjugateGradient, TwoUnknownsTakeTwoSteps) {
  const Tridiagonal A(2);  // [[2.1, -1], [-1, 2.15]]
  std::vector<double> b{1.0, 0.0}, x{0.0, 0.0};
  const ConjugateGradientReport r = solve(A, b, x, 1e-14, 50);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 2);
  const double det = 2.1 * 2.15 - 1.0;
  EXPECT_NEAR(x[0], 2.15 / det, 1e-14);
  EXPECT_NEAR(x[1], 1.0 / det, 1e-14);
}

TEST(ConjugateGradient, ZeroRightHandSideGivesZeroAndTheIterationCapIsReported) {
  const Tridiagonal A(50);
  std::vector<double> b(50, 0.0), x(50, 3.0);
  EXPECT_EQ(solve(A, b, x, 1e-10, 100).iterations, 0);
  for (const double v : x) EXPECT_EQ(v, 0.0);
  std::vector<double> c(50, 1.0), y(50, 0.0);
  const ConjugateGradientReport capped = solve(A, c, y, 1e-15, 2);
  EXPECT_FALSE(capped.converged);
  EXPECT_EQ(capped.iterations, 2);
  EXPECT_GT(capped.error, 1e-15);
}

// Enough rows for the loops to run in parallel: 1 and 2 threads give the same bits (exact dot products).
TEST(ConjugateGradient, OneAndTwoThreadsGiveTheSameBits) {
  const Tridiagonal A(3 * static_cast<std::size_t>(parallel_threshold));
  std::vector<double> b(A.size());
  for (std::size_t i = 0; i < A.size(); ++i) b[i] = std::cos(0.37 * static_cast<double>(i));
  const int saved = thread_count();
  std::vector<std::vector<double>> x(2, std::vector<double>(A.size(), 0.0));
  for (int t : {1, 2}) {
    set_thread_count(t);
    solve(A, b, x[static_cast<std::size_t>(t - 1)], 1e-10, 500);
  }
  set_thread_count(saved);
  EXPECT_EQ(0, std::memcmp(x[0].data(), x[1].data(), x[0].size() * sizeof(double)));
}

}  // namespace
}  // namespace slide
