#pragma once
// The semi-implicit viscous step: the viscous term of fluid/viscosity.hpp taken at the new velocities, with the
// viscosities lagged (evaluated from the velocities at the start of the step).
//
// Why: with a yield stress the regularised viscosity is huge where the material is at rest, and an explicit viscous
// step must then be 40-1000x smaller than the acoustic (CFL) step (DESIGN.md, measured), although the regularisation
// changes the answer by under 0.03 %. Taken implicitly the viscous term is unconditionally stable and the step is
// set by the CFL limit alone.
//
// For every fluid particle i (c = 2d / (lambda n0), seed eq. 4; mu_ij the harmonic mean across a pair; walls
// mirrored as in viscous_pair_term, factor f_ij = no_slip_mirror_factor, with the wall's velocity u_b and the wall
// viscosity mu_w,i = s_i mu_i, lagged like mu_i: fluid/basal_friction.hpp):
//   rho_i u*_i - dt c [ sum_fluid mu_ij W_ij (u*_j - u*_i) + sum_wall mu_w,i f_ij W_ij (u_b,j - u*_i) ]
//       = rho_i (u_i + dt a_i),
// a_i the explicit accelerations (gravity, artificial viscosity). Multiplied by rho_i (not divided), the matrix is
// symmetric (mu_ij W_ij = mu_ji W_ji) and strictly diagonally dominant with a positive diagonal, hence symmetric
// positive definite: one system, solved by conjugate gradients with a diagonal (Jacobi) preconditioner, serves every
// velocity component (the mirrored wall acts on each component alike). Free-slip walls are left out, as in the
// explicit term. The step (coupling/simulation.cpp) then applies the explicit operator's pair terms at the solution
// u~, to the fluid and, through body particles, to the bodies: momentum is then exchanged exactly, whatever the
// solver's tolerance, and the result differs from u~ only by the solver's residual.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"
#include "fluid/strain_rate.hpp"
#include "fluid/viscosity.hpp"

namespace slide {

struct ViscousSolveReport {
  int iterations = 0;     // the most over the velocity components
  double residual = 0.0;  // the largest relative residual |b - A u| / |b| reached
  bool converged = true;
};

// Matrix workspace kept between steps (its arrays are reused).
class ImplicitViscosity {
 public:
  double tolerance = 1e-8;    // relative residual
  int max_iterations = 500;

  // Replaces P.velocity of every real fluid particle by the solution (above); `explicit_acceleration` holds a_i for
  // fluid particles. Positions are not moved. Particles other than fluid keep their velocities; periodic ghosts are
  // left for the caller to copy.
  template <int D>
  ViscousSolveReport solve(Particles<D>& P, const NeighborList& nl, double re, double n0, double lambda,
                           const ViscousWall& wall, double dt, const std::vector<Vec<D>>& explicit_acceleration);

 private:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  std::vector<int> row_of_;        // particle -> unknown (-1: not fluid)
  std::vector<std::uint32_t> particle_of_;  // unknown -> particle
  std::vector<int> row_start_;
  Matrix matrix_;  // compressed row storage, filled in place
};

template <int D>
ViscousSolveReport ImplicitViscosity::solve(Particles<D>& P, const NeighborList& nl, double re, double n0,
                                            double lambda, const ViscousWall& wall, double dt,
                                            const std::vector<Vec<D>>& explicit_acceleration) {
  // Unknowns: the real fluid particles. A periodic ghost (fluid/periodic.hpp) is its source's unknown.
  const std::size_t n = P.real_count();
  row_of_.assign(n, -1);
  particle_of_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (P.kind[i] == Kind::fluid) {
      row_of_[i] = static_cast<int>(particle_of_.size());
      particle_of_.push_back(static_cast<std::uint32_t>(i));
    }
  const std::size_t rows = particle_of_.size();
  ViscousSolveReport report;
  if (rows == 0) return report;
  const double re2 = re * re, c = 2.0 * D / (lambda * n0);

  // Row sizes: the diagonal and every fluid neighbour within re.
  row_start_.assign(rows + 1, 0);
  parallel_for(rows, [&](std::size_t r) {
    const std::size_t i = particle_of_[r];
    int count = 1;
    for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q)
      if (P.kind[*q] == Kind::fluid && distance_squared<D>(P.position[*q], P.position[i]) < re2) ++count;
    row_start_[r + 1] = count;
  });
  for (std::size_t r = 0; r < rows; ++r) row_start_[r + 1] += row_start_[r];
  matrix_.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(rows));
  matrix_.resizeNonZeros(row_start_[rows]);
  std::copy(row_start_.begin(), row_start_.end(), matrix_.outerIndexPtr());
  int* column = matrix_.innerIndexPtr();
  double* value = matrix_.valuePtr();
  Eigen::Matrix<double, Eigen::Dynamic, D> rhs(rows, D), u(rows, D);

  // Rows: off-diagonals -dt c mu_ij W_ij, the diagonal rho_i + dt c (sum mu_ij W_ij + sum_wall mu_i f_ij W_ij),
  // the right-hand side rho_i (u_i + dt a_i) + dt c sum_wall mu_i f_ij W_ij u_b,j. Columns sorted within a row.
  parallel_for(rows, [&](std::size_t r) {
    const std::size_t i = particle_of_[r];
    const double mu_i = P.viscosity[i];
    Vec<D> b = P.density[i] * (P.velocity[i] + dt * explicit_acceleration[i]);
    double diagonal = P.density[i];
    std::vector<std::pair<int, double>> entries;
    entries.reserve(row_start_[r + 1] - row_start_[r]);
    for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
      const std::uint32_t j = *q;
      const double r2 = distance_squared<D>(P.position[j], P.position[i]);
      if (r2 >= re2) continue;
      const double w = kernel_weight(std::sqrt(r2), re);
      if (P.kind[j] == Kind::fluid) {
        const double mu_j = P.viscosity[j];
        const double mu_ij = mu_i == mu_j ? mu_i : 2.0 * mu_i * mu_j / (mu_i + mu_j);
        const double a = dt * c * mu_ij * w;
        diagonal += a;
        entries.emplace_back(row_of_[P.real_index(j)], -a);
      } else if (wall.slip == WallSlip::no_slip) {
        const double d_j = P.wall_depth[j];
        const double d_i = P.wall_normal[j].dot(P.position[i] - P.position[j]) - d_j;
        const double a = dt * c * mu_i * P.wall_fraction[i] * no_slip_mirror_factor(d_i, d_j, wall.min_distance) * w;
        diagonal += a;
        b += a * P.velocity[j];
      }
    }
    entries.emplace_back(static_cast<int>(r), diagonal);
    std::sort(entries.begin(), entries.end());
    int k = row_start_[r];
    for (const auto& [col, v] : entries) {
      column[k] = col;
      value[k] = v;
      ++k;
    }
    rhs.row(r) = b.transpose();
    u.row(r) = (P.velocity[i] + dt * explicit_acceleration[i]).transpose();
  });

  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(max_iterations);
  cg.compute(matrix_);
  for (int d = 0; d < D; ++d) {
    if (rhs.col(d).squaredNorm() == 0.0) {
      u.col(d).setZero();
      continue;
    }
    Eigen::VectorXd x = cg.solveWithGuess(rhs.col(d), u.col(d));
    u.col(d) = x;
    report.iterations = std::max(report.iterations, static_cast<int>(cg.iterations()));
    report.residual = std::max(report.residual, cg.error());
    report.converged = report.converged && cg.info() == Eigen::Success;
  }
  parallel_for(rows, [&](std::size_t r) { P.velocity[particle_of_[r]] = u.row(r).transpose(); });
  return report;
}

}  // namespace slide
