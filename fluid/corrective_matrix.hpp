#pragma once
// The corrective matrix of the corrected pressure gradient (fluid/gradient.hpp, GradientModel::corrected):
//   L_i = A_i^-1,  A_i = 1 / (kappa n0) * sum_j (-W'(r_ij)) r_ij (x) r_ij / |r_ij|,
// over every neighbour within re (fluid and boundary), with kappa n0 = sum (-W' r) / d of the regular lattice, so that
// A = L = I there (Bonet & Lok 1999; Khayyer & Gotoh 2011). A particle whose support is cut keeps L = I: a free-surface
// particle (n_i < beta n0: its A lacks the missing side, and its inverse would amplify the pressure across the surface
// without bound); beside it, the correction fades in with the support (below).
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// The smallest eigenvalue of a symmetric matrix in closed form (2-D: the trace's half less the radius of Mohr's circle;
// 3-D: Eigen's direct solver). Eigen's iterative solver took 16 % of a sediment step (perf, issue 29).
template <int D>
double smallest_eigenvalue(const Mat<D>& A) {
  if constexpr (D == 2) {
    const double centre = 0.5 * (A(0, 0) + A(1, 1)), half_difference = 0.5 * (A(0, 0) - A(1, 1));
    const double off_diagonal = 0.5 * (A(0, 1) + A(1, 0));
    return centre - std::sqrt(half_difference * half_difference + off_diagonal * off_diagonal);
  } else {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> solver;
    solver.computeDirect(Eigen::Matrix<double, D, D>(A), Eigen::EigenvaluesOnly);
    return solver.eigenvalues().minCoeff();
  }
}

// Whether a symmetric matrix's smallest eigenvalue is at least t: A - t I positive semi-definite (2-D: its diagonal
// and determinant not negative; 3-D: from the eigenvalues).
template <int D>
bool smallest_eigenvalue_at_least(const Mat<D>& A, double t) {
  if constexpr (D == 2) {
    const double a = A(0, 0) - t, c = A(1, 1) - t;
    return a >= 0.0 && c >= 0.0 && a * c >= A(0, 1) * A(1, 0);
  } else {
    return smallest_eigenvalue<D>(A) >= t;
  }
}

// A_i's sum before its division by kappa n0, one pair at a time: sum (-W'(r_ij) / r_ij) r_ij (x) r_ij over i's
// listed neighbours within re. The pressure stage takes the same sum in lanes with the number density
// (fluid/listed_pairs.hpp). The corrected gradient's cost per particle-step on the Rzadkiewicz slide (dp 0.02, 1
// thread, against variational): 2.6-2.9x with this sum, Eigen's eigenvalue solver and the predictor's own pass;
// 1.15x with the lanes and the closed-form eigenvalue; 1.06-1.09x with the gradient's loop unbranched (issue 29).
template <int D>
Mat<D> kernel_second_moment(std::size_t i, const std::vector<Vec<D>>& x, const NeighborList& nl, double re) {
  const double re2 = re * re;
  Mat<D> M = Mat<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const Vec<D> rij = x[*q] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 < re2) M += derivative_over_r(std::sqrt(r2), re) * (rij * rij.transpose());
  }
  return M;
}

// L from A = moment / (kappa n0), faded towards I where A's smallest eigenvalue is low (below).
template <int D>
Mat<D> faded_inverse(const Mat<D>& moment, double kappa_n0) {
  const Mat<D> A = (1.0 / kappa_n0) * moment;
  // A cut support lacks second moment across the cut, and A's smallest eigenvalue falls below 1 (on the hexagonal
  // lattice under a flat surface: 0.94 in the row below the surface's, 1.00 in the next). The correction fades to none
  // as that eigenvalue falls from 0.97 to 0.90. Why, measured on the shipped still tank (largest speed over 1 s in
  // snapshots 0.05 s apart, in % of sqrt(g H)) and a 0.2 x 0.1 m box towed at 0.05 m/s through still water (dp 0.01;
  // resistance over 0.3-1 / 1-2 / 2-3 s, N/m; uncorrected -21 / -16 / -14):
  //   no fade (corrected up to the surface's row): 4.1 %; -2.4 / -1.0 / -0.8
  //   fade over [0.85, 0.95]: 0.45 %; -2.5 / -1.2 / -1.8        [0.90, 0.97]: 0.05 %; -3.6 / -2.8 / -2.5
  //   fade over [0.95, 0.99]: 0.34 %; -6.1 / -6.8 / -5.9        [0.80, 0.90]: 1.4 %
  //   fade only beside a free-surface particle (full correction elsewhere), over [0.95, 0.99]: 2.1 %; [0.90, 0.97]: 4.2 %.
  // Below 0.97 the support is cut or the particles stand apart (a lattice stretched 3 % along x has 0.96 and 0.97),
  // and A^-1 amplifies their pressure forces: corrected there, the rows under a free surface were pushed about.
  // The price: a dilated region (a flowing slide) is corrected less. The Grilli slide's front at 0.17 / 0.32 / 0.47 /
  // 0.62 s (dp 0.008), in % of the measured travel: uncorrected -44 / -70 / -71 / -73; no fade -8 / -40 / -52 / -55;
  // [0.90, 0.97] -34 / -60 / -60 / -61.
  constexpr double none = 0.90, all = 0.97;
  const Mat<D> A_inverse = A.inverse();
  if (smallest_eigenvalue_at_least<D>(A, all)) return A_inverse;  // most particles: no square root
  const double full = std::clamp((smallest_eigenvalue<D>(A) - none) / (all - none), 0.0, 1.0);
  if (full == 0.0) return Mat<D>::Identity();
  return Mat<D>::Identity() + full * (A_inverse - Mat<D>::Identity());
}

// Particle i's L at the present positions: I for a boundary or free-surface particle (above).
template <int D>
Mat<D> corrective_matrix(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                         double kappa, double surface_n) {
  if (P.kind[i] != Kind::fluid || P.number_density[i] < surface_n) return Mat<D>::Identity();
  return faded_inverse<D>(kernel_second_moment<D>(i, P.position, nl, re), kappa * n0);
}

}  // namespace slide
