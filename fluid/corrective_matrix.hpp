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

template <int D>
Mat<D> corrective_matrix(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                         double kappa, double surface_n) {
  if (P.kind[i] != Kind::fluid || P.number_density[i] < surface_n) return Mat<D>::Identity();
  const double re2 = re * re;
  Mat<D> A = Mat<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const Vec<D> rij = P.position[*q] - P.position[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    A += derivative_over_r(std::sqrt(r2), re) * (rij * rij.transpose());
  }
  A /= kappa * n0;
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
  const Eigen::Matrix<double, D, D> symmetric_A = A;
  const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>>(symmetric_A,
                                                                                     Eigen::EigenvaluesOnly)
                              .eigenvalues()
                              .minCoeff();
  const double full = std::clamp((smallest - 0.90) / (0.97 - 0.90), 0.0, 1.0);
  if (full == 0.0) return Mat<D>::Identity();
  return Mat<D>::Identity() + full * (Mat<D>(A.inverse()) - Mat<D>::Identity());
}

}  // namespace slide
