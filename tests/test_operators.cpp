// MPS operators on a regular lattice against exact answers: the number density equals n0, every gradient model
// reproduces a linear field's gradient, the Laplacian a quadratic field's Laplacian (interior particles).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "fluid/corrective_matrix.hpp"
#include "fluid/equation_of_state.hpp"
#include "fluid/gradient.hpp"
#include "fluid/laplacian.hpp"
#include "fluid/lattice.hpp"
#include "fluid/number_density.hpp"
#include "fluid/pair_weights.hpp"
#include "tests/bit_pattern.hpp"
#include "tests/lattice_block.hpp"

namespace slide {
namespace {

using testing::Lattice;

using testing::bits;


template <int D>
void expect_number_density_is_n0(LatticeKind kind = LatticeKind::square) {
  Lattice<D> L(kind);
  std::vector<double> n;
  compute_number_density<D>(L.particles.position, L.list, L.re, n);
  for (std::size_t i = 0; i < n.size(); ++i)
    if (L.interior(i)) {
      EXPECT_NEAR(n[i], L.constants.n0, 1e-12);
    }
}
TEST(Operators, NumberDensityIsN0OnLattice2D) { expect_number_density_is_n0<2>(); }
TEST(Operators, NumberDensityIsN0OnLattice3D) { expect_number_density_is_n0<3>(); }
TEST(Operators, NumberDensityIsN0OnHexagonalLattice) { expect_number_density_is_n0<2>(LatticeKind::hexagonal); }

template <int D>
void expect_gradient_of_linear_field_exact(LatticeKind kind = LatticeKind::square) {
  Lattice<D> L(kind);
  Vec<D> slope;
  for (int k = 0; k < D; ++k) slope[k] = 1.5 + 2.0 * k;
  for (std::size_t i = 0; i < L.particles.size(); ++i) L.particles.pressure[i] = 300.0 + slope.dot(L.particles.position[i]);
  for (GradientModel m : {GradientModel::standard, GradientModel::pmin, GradientModel::symmetric,
                          GradientModel::variational, GradientModel::difference}) {
    for (std::size_t i = 0; i < L.particles.size(); ++i) {
      if (!L.interior(i)) continue;
      const Vec<D> g = pressure_gradient<D>(m, i, L.particles, L.list, L.re, L.constants.n0, L.constants.kappa);
      for (int k = 0; k < D; ++k) ASSERT_NEAR(g[k], slope[k], 1e-9 * slope.norm()) << to_string(m) << " particle " << i;
    }
    // The seed's eq. 3 applied to any field agrees.
    const Vec<D> g = mps_gradient<D>(L.centre, L.particles.position, L.particles.pressure, L.list, L.re, L.constants.n0);
    for (int k = 0; k < D; ++k) EXPECT_NEAR(g[k], slope[k], 1e-9 * slope.norm());
  }
}
TEST(Operators, GradientOfLinearFieldExact2D) { expect_gradient_of_linear_field_exact<2>(); }
TEST(Operators, GradientOfLinearFieldExact3D) { expect_gradient_of_linear_field_exact<3>(); }
// The hexagonal lattice's second moments are isotropic too, so every model is exact on it with its own n0 and kappa.
TEST(Operators, GradientOfLinearFieldExactHexagonal) {
  expect_gradient_of_linear_field_exact<2>(LatticeKind::hexagonal);
}

// The corrected gradient (fluid/gradient.hpp) on a lattice squeezed by x -> F x: every particle with a
// full support has the same second moment A = F A0 F^T / (kappa n0), and the corrective matrix makes the gradient of a
// linear field exact there, where the plain variational form is not (a uniform pressure's stress is then anisotropic).
// On the unsheared lattice L = I: the corrected model is the variational one.
TEST(Operators, CorrectedGradientIsExactOnAShearedLattice) {
  for (const bool sheared : {false, true}) {
    Lattice<2> L(LatticeKind::hexagonal);
    auto& P = L.particles;
    Mat<2> F = Mat<2>::Identity();
    // Squeezed 4 % along x: A's eigenvalues 1.048 and 1.061, fully corrected (corrective_matrix.hpp fades the
    // correction out below 0.97, where a support is cut).
    if (sheared) F << 0.96, 0.0, 0.0, 1.0;
    for (auto& x : P.position) x = F * x;
    NeighborGrid<2> grid(Vec<2>::Constant(-2 * L.dp), Vec<2>::Constant((L.side + 4) * L.dp), L.re);
    grid.bin(P.position);
    build_neighbor_list(grid, P.position, L.re, L.list);
    for (auto& n : P.number_density) n = L.constants.n0;  // none counts as a free-surface particle
    const Mat<2> Lc = corrective_matrix<2>(L.centre, P, L.list, L.re, L.constants.n0, L.constants.kappa, 0.0);
    if (!sheared) {
      EXPECT_NEAR((Lc - Mat<2>::Identity()).norm(), 0.0, 1e-12);
    }
    P.gradient_correction.assign(P.size(), Lc);  // homogeneous: every full support has this one
    const Vec<2> slope(3.5, -1.5);
    for (std::size_t i = 0; i < P.size(); ++i) P.pressure[i] = 300.0 + slope.dot(P.position[i]);
    const Vec<2> corrected = pressure_gradient<2>(GradientModel::corrected, L.centre, P, L.list, L.re,
                                                  L.constants.n0, L.constants.kappa);
    const Vec<2> plain = pressure_gradient<2>(GradientModel::variational, L.centre, P, L.list, L.re, L.constants.n0,
                                              L.constants.kappa);
    EXPECT_NEAR((corrected - slope).norm(), 0.0, 1e-9 * slope.norm()) << (sheared ? "sheared" : "regular");
    if (sheared) {
      EXPECT_GT((plain - slope).norm(), 0.03 * slope.norm());  // what the correction is for
    } else {
      EXPECT_NEAR((plain - corrected).norm(), 0.0, 1e-9 * slope.norm());
    }
  }
}

// The closed-form smallest eigenvalue (fluid/corrective_matrix.hpp) against Eigen's iterative solver, and the test
// "smallest eigenvalue at least t" without one, on random symmetric matrices near I (where the fade decides).
template <int D>
void expect_smallest_eigenvalue_agrees() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> entry(-0.15, 0.15);
  int above = 0, below = 0;
  for (int k = 0; k < 2000; ++k) {
    Mat<D> A = Mat<D>::Identity();
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) A(a, b) = A(b, a) = A(a, b) + entry(rng);
    const double exact = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>>(Eigen::Matrix<double, D, D>(A))
                             .eigenvalues()
                             .minCoeff();
    ASSERT_NEAR(smallest_eigenvalue<D>(A), exact, 1e-13);
    for (const double t : {0.90, 0.97}) {
      if (std::abs(exact - t) < 1e-12) continue;
      ASSERT_EQ(smallest_eigenvalue_at_least<D>(A, t), exact >= t) << "eigenvalue " << exact << ", t " << t;
      (exact >= t ? above : below) += 1;
    }
  }
  EXPECT_GT(above, 100);
  EXPECT_GT(below, 100);
}
TEST(Operators, SmallestEigenvalueInClosedFormAgrees2D) { expect_smallest_eigenvalue_agrees<2>(); }
TEST(Operators, SmallestEigenvalueInClosedFormAgrees3D) { expect_smallest_eigenvalue_agrees<3>(); }

// The second moment the number density's stage takes in lanes with the weights (fluid/listed_pairs.hpp) equals the
// pair-by-pair one (corrective_matrix.hpp) to rounding, and the weights and factors it keeps are unchanged, bit for
// bit, by taking it: on jittered particles with a list built with a skin, 2-D and 3-D.
template <int D>
void expect_lane_moment_agrees() {
  Lattice<D> L;
  auto& P = L.particles;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2 * L.dp, 0.2 * L.dp);
  for (auto& x : P.position)
    for (int c = 0; c < D; ++c) x[c] += jitter(rng);
  const double list_radius = L.re + 0.3 * L.dp;
  NeighborGrid<D> grid(Vec<D>::Constant(-L.dp), Vec<D>::Constant((L.side + 2) * L.dp), list_radius);
  grid.bin(P.position);
  NeighborList list;
  build_neighbor_list(grid, P.position, list_radius, list);
  std::vector<double> with(256), without(256);
  for (std::size_t i = 0; i < P.size(); ++i) {
    ASSERT_LE(list.count[i], with.size());
    Mat<D> lanes;
    const double n_with = number_density_keeping_weights<D>(i, P.position, nullptr, list, L.re, with.data(),
                                                            PairFactor::derivative_over_r, &lanes);
    const double n_without = number_density_keeping_weights<D>(i, P.position, nullptr, list, L.re, without.data(),
                                                               PairFactor::derivative_over_r);
    ASSERT_EQ(bits(n_with), bits(n_without));
    for (std::size_t k = 0; k < list.count[i]; ++k) ASSERT_EQ(bits(with[k]), bits(without[k]));
    const Mat<D> pairwise = kernel_second_moment<D>(i, P.position, list, L.re);
    ASSERT_GT(pairwise.norm(), 0.0);
    ASSERT_NEAR((lanes - pairwise).norm(), 0.0, 1e-12 * pairwise.norm()) << "particle " << i;
  }
}
TEST(Operators, SecondMomentTakenInLanesAgrees2D) { expect_lane_moment_agrees<2>(); }
TEST(Operators, SecondMomentTakenInLanesAgrees3D) { expect_lane_moment_agrees<3>(); }


// The gradient summed pair by pair, each pair's factor computed on its own and pairs beyond re skipped.
Vec<2> pair_by_pair_gradient(GradientModel m, std::size_t i, const Particles<2>& P, const NeighborList& nl, double re,
                             double n0, double kappa) {
  switch (m) {
    case GradientModel::standard: return pressure_gradient_of<2, GradientModel::standard>(i, P, nl, re, n0);
    case GradientModel::pmin: return pressure_gradient_of<2, GradientModel::pmin>(i, P, nl, re, n0);
    case GradientModel::symmetric: return pressure_gradient_of<2, GradientModel::symmetric>(i, P, nl, re, n0);
    case GradientModel::variational: return derivative_pressure_gradient<2, true>(i, P, nl, re, n0, kappa);
    case GradientModel::difference: return derivative_pressure_gradient<2, false>(i, P, nl, re, n0, kappa);
    case GradientModel::corrected: break;  // tested on its own (CorrectedGradientIsExactOnAShearedLattice)
  }
  return Vec<2>::Zero();
}

// The pair factors the number density keeps (fluid/pair_weights.hpp) give the same number densities and, read by the
// pressure gradient at the same positions, the same gradients as the pair-by-pair sums, bit for bit, for every model
// (W / r^2 or -W'(r) / r as it reads), as does the gradient that takes its factors itself: on disordered particles
// with a wall row (normal split), filled boundary particles, and a list built with a skin (listed pairs beyond re have
// factor 0).
TEST(Operators, KeptPairWeightsGiveBitIdenticalNumberDensityAndGradients) {
  Lattice<2> L;
  auto& P = L.particles;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.2 * L.dp, 0.2 * L.dp), fill(0.5, 1.0), p(-50.0, 900.0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.position[i] += Vec<2>(jitter(rng), jitter(rng));
    P.pressure[i] = p(rng);
    if (P.position[i][1] < 0.5 * L.dp) {
      P.kind[i] = Kind::wall;
      P.wall_normal[i] = Vec<2>(0.0, 1.0);
      P.wall_fill[i] = fill(rng);
    }
  }
  NeighborGrid<2> grid(Vec<2>::Constant(-L.dp), Vec<2>::Constant((L.side + 2) * L.dp), L.re + 0.3 * L.dp);
  grid.bin(P.position);
  NeighborList list;
  build_neighbor_list(grid, P.position, L.re + 0.3 * L.dp, list);
  PairWeights weights;
  weights.shape_like(list);
  std::size_t beyond_re = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const std::vector<double>* no_fill = nullptr;
    for (const std::vector<double>* f : {no_fill, static_cast<const std::vector<double>*>(&P.wall_fill)}) {
      const double kept = number_density_keeping_weights<2>(i, P.position, f, list, L.re, weights.of(list, i));
      const double plain = f ? weighted_number_density_of<2>(i, P.position, P.wall_fill, list, L.re)
                             : number_density_of<2>(i, P.position, list, L.re);
      ASSERT_EQ(kept, plain) << "particle " << i;
    }
    const double* w = weights.of(list, i);
    for (std::size_t k = 0; k < list.count[i]; ++k) beyond_re += w[k] == 0.0;
    for (GradientModel m : {GradientModel::standard, GradientModel::pmin, GradientModel::symmetric,
                            GradientModel::variational, GradientModel::difference}) {
      // The factor this model reads, kept by the number density's stage (whose sum does not depend on it).
      const double kept = number_density_keeping_weights<2>(i, P.position, nullptr, list, L.re, weights.of(list, i),
                                                            kept_pair_factor(m));
      ASSERT_EQ(kept, number_density_of<2>(i, P.position, list, L.re)) << "particle " << i;
      const Vec<2> read = pressure_gradient<2>(m, i, P, list, L.re, L.constants.n0, L.constants.kappa, w);
      const Vec<2> taken = pressure_gradient<2>(m, i, P, list, L.re, L.constants.n0, L.constants.kappa);
      const Vec<2> pairwise = pair_by_pair_gradient(m, i, P, list, L.re, L.constants.n0, L.constants.kappa);
      for (int k = 0; k < 2; ++k) {
        ASSERT_EQ(bits(read[k]), bits(pairwise[k])) << to_string(m) << " particle " << i;
        ASSERT_EQ(bits(taken[k]), bits(pairwise[k])) << to_string(m) << " particle " << i;
      }
    }
  }
  EXPECT_GT(beyond_re, P.size());  // the skin lists pairs beyond re, whose kept weight is 0
}

// The kept factors are read only at the step, and as the factor, they were taken at: the gradient falls back to
// taking its own otherwise, with the same result, so a guard that always failed would show only in the speed.
TEST(Operators, KeptPairFactorsAreReadOnlyWhereTaken) {
  NeighborList list;
  list.blocks.assign(2, std::vector<std::uint32_t>(3));
  PairWeights kept;
  kept.shape_like(list);
  EXPECT_FALSE(kept.taken_at(0, PairFactor::w_over_r2));
  kept.mark_taken_at(7, PairFactor::derivative_over_r);
  EXPECT_TRUE(kept.taken_at(7, PairFactor::derivative_over_r));
  EXPECT_FALSE(kept.taken_at(7, PairFactor::w_over_r2));
  EXPECT_FALSE(kept.taken_at(8, PairFactor::derivative_over_r));
  kept.forget();
  EXPECT_FALSE(kept.taken_at(7, PairFactor::derivative_over_r));
  kept.mark_taken_at(9, PairFactor::w_over_r2);
  kept.shape_like(list);  // a new list's shape: nothing taken on it yet
  EXPECT_FALSE(kept.taken_at(9, PairFactor::w_over_r2));
}

template <int D>
void expect_laplacian_of_quadratic_field_exact(LatticeKind kind = LatticeKind::square) {
  Lattice<D> L(kind);
  // phi = sum_k c_k x_k^2 + x_0 x_1: Laplacian 2 sum c_k.
  std::vector<double> phi(L.particles.size());
  double exact = 0.0;
  for (int k = 0; k < D; ++k) exact += 2.0 * (1.0 + k);
  for (std::size_t i = 0; i < phi.size(); ++i) {
    const auto& x = L.particles.position[i];
    phi[i] = x[0] * x[1];
    for (int k = 0; k < D; ++k) phi[i] += (1.0 + k) * x[k] * x[k];
  }
  for (std::size_t i = 0; i < phi.size(); ++i)
    if (L.interior(i)) {
      ASSERT_NEAR(mps_laplacian<D>(i, L.particles.position, phi, L.list, L.re, L.constants.n0, L.constants.lambda),
                  exact, 1e-9 * exact);
    }
  // A vector field: each component separately.
  std::vector<Vec<D>> u(L.particles.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = Vec<D>::Constant(phi[i]);
  const Vec<D> lap = mps_laplacian<D>(L.centre, L.particles.position, u, L.list, L.re, L.constants.n0, L.constants.lambda);
  for (int k = 0; k < D; ++k) EXPECT_NEAR(lap[k], exact, 1e-9 * exact);
}
TEST(Operators, LaplacianOfQuadraticFieldExact2D) { expect_laplacian_of_quadratic_field_exact<2>(); }
TEST(Operators, LaplacianOfQuadraticFieldExact3D) { expect_laplacian_of_quadratic_field_exact<3>(); }
TEST(Operators, LaplacianOfQuadraticFieldExactHexagonal) {
  expect_laplacian_of_quadratic_field_exact<2>(LatticeKind::hexagonal);
}

TEST(EquationOfState, SeedEquation7AndInverse) {
  const EquationOfState eos(2.0, 20.0, 7.0);
  EXPECT_DOUBLE_EQ(eos.pressure(2.0, 1000.0), 0.0);
  const double n = 2.02;
  const double expected = 1000.0 * 400.0 / 7.0 * (std::pow(1.01, 7.0) - 1.0);
  EXPECT_NEAR(eos.pressure(n, 1000.0), expected, 1e-9 * expected);
  EXPECT_NEAR(eos.number_density_ratio(expected, 1000.0), 1.01, 1e-12);
  // Non-integral gamma goes through std::pow.
  const EquationOfState eos2(1.0, 10.0, 1.5);
  EXPECT_NEAR(eos2.pressure(1.1, 1000.0), 1000.0 * 100.0 / 1.5 * (std::pow(1.1, 1.5) - 1.0), 1e-9);
}

}  // namespace
}  // namespace slide
