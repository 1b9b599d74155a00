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
//
// Images (fluid/ghosts.hpp). A periodic image's velocity is its source's, a mirror image's its source's with the
// components across the plane negated: a fluid neighbour that is an image of unknown s enters s's column with the sign
// of the image for each component (so a component's matrix differs from another's where mirrors flip it; each stays
// symmetric, as the image of i near s is flipped like that of s near i, and diagonally dominant), and an image of the
// row's own particle enters its diagonal: a (1 - sign) for u_i's coupling to its image, 0 for a periodic image's.
// A particle on a plane of symmetry has no image (it is its own) but its neighbours' images count: the system it
// belongs to is the whole one restricted to mirror-symmetric velocities, whose rows are the modelled side's with the
// on-plane particle's row weighted by its share of the modelled side (1/2 per plane it lies on), so that the matrix
// stays symmetric; its velocity across such a plane is zero (hold_on_planes), which its row and column then say.
//
// Which particles are unknowns. Write the system A u~ = b, A = R + K, R = diag(rho_i), and let a fluid particle's
// viscous number be s_i = (sum of its row's off-diagonal and wall coefficients) / rho_i = dt c (sum_fluid mu_ij W_ij
// + sum_wall mu_i f_ij W_ij) / rho_i (viscous_row_number below): the fraction of its velocity difference that
// viscosity relaxes in one step; the explicit term is stable for s_i <= 1 (Gershgorin), the explicit time-step limit.
// Only the stiff particles, s_i > eps = sqrt(tolerance), are unknowns (Bingham sediment: s ~ 1e2-1e6); the others
// (water: s ~ 1e-5 at the CFL step) take u~_i = u_i + dt a_i, which enters the stiff rows like a wall's velocity.
// The stiff rows form a principal submatrix of A, so that system is again symmetric and strictly diagonally
// dominant, positive definite. The error: with e = u~ - u_exact, e_i <= s_i |du| on a non-stiff row (|du| the
// largest velocity difference), a stiff row solved against it gets e_i <= sum_j k_ij e_j / rho_i, k_ij <= s_j rho_j,
// i.e. O(eps^2); and the step's result u* = R^-1 (b - K u~) = u_exact - R^-1 K e is O(eps^2 |du|) from the fully
// implicit answer on every row: within the solver's tolerance. Non-stiff rows are thereby updated explicitly
// (u* = u + dt (a + a_visc(u~))) at s_i <= eps, 1/eps inside the explicit stability limit; the stiff rows implicitly
// as before. Momentum stays exact (the same pair terms, at u~, go both ways).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/conjugate_gradient.hpp"
#include "fluid/domain.hpp"
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

// The implicit couplings of fluid particle i (the row of the system above, before multiplying by dt c): calls
// fluid(j, mu_ij W_ij) for each fluid neighbour j within re and wall(j, mu_i f_ij W_ij) for each boundary neighbour
// under a no-slip wall (free slip: none).
template <int D, class Fluid, class Wall>
inline void for_each_viscous_coupling(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re,
                                      const ViscousWall& wall, Fluid&& fluid, Wall&& wall_pair) {
  const double re2 = re * re;
  const double mu_i = P.viscosity[i];
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    const double r2 = distance_squared<D>(P.position[j], P.position[i]);
    if (r2 >= re2) continue;
    const double w = kernel_weight(std::sqrt(r2), re);
    if (P.kind[j] == Kind::fluid) {
      const double mu_j = P.viscosity[j];
      const double mu_ij = mu_i == mu_j ? mu_i : 2.0 * mu_i * mu_j / (mu_i + mu_j);
      fluid(j, mu_ij * w);
    } else if (wall.slip == WallSlip::no_slip) {
      const double d_j = P.wall_depth[j];
      const double d_i = P.wall_normal[j].dot(P.position[i] - P.position[j]) - d_j;
      // The wall viscosity s_i mu_i (Particles::wall_fraction: 1 at a no-slip wall, below 1 where a Coulomb basal
      // friction lets the particle slide), as in viscous_pair_term.
      wall_pair(j, mu_i * P.wall_fraction[i] * no_slip_mirror_factor(d_i, d_j, wall.min_distance) * w);
    }
  }
}

// One walk over fluid particle i's neighbours: its viscous row number s_i (header), dt c (sum_fluid mu_ij W_ij +
// sum_wall mu_i f_ij W_ij) / rho_i, c = 2d / (lambda n0), and its explicit viscous acceleration at the present
// velocities, the same sum as viscous_acceleration (fluid/viscosity.hpp) in the same order, hence the same value
// (for finite velocities: viscous_acceleration adds the zero terms of fluid neighbours beyond re, this skips them).
template <int D>
struct ViscousRow {
  double number = 0.0;
  Vec<D> acceleration = Vec<D>::Zero();
};

template <int D>
ViscousRow<D> viscous_row(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                          double lambda, const ViscousWall& wall, double dt) {
  double coupling_sum = 0.0;
  Vec<D> sum = Vec<D>::Zero();
  auto add = [&](std::uint32_t j, double coupling) {
    coupling_sum += coupling;
    sum += coupling * (P.velocity[j] - P.velocity[i]);
  };
  for_each_viscous_coupling<D>(i, P, nl, re, wall, add, add);
  return {dt * (2.0 * D / (lambda * n0)) * coupling_sum / P.density[i], viscous_scale<D>(i, P, n0, lambda) * sum};
}

// Matrix workspace kept between steps (its arrays are reused).
class ImplicitViscosity {
 public:
  double tolerance = 1e-8;    // relative residual
  int max_iterations = 500;

  double stiff_row_number() const { return std::sqrt(tolerance); }

  // Several processes (fluid/domain.hpp): each holds the rows of its own unknowns; a row's columns are unknowns of any
  // process, read through the ghosts, and the solver's dot products are exact sums combined across processes, so the
  // solution is the same to the bit on any number of processes.
  template <int D>
  ViscousSolveReport solve(Domain<D>& domain, const NeighborList& nl, double re, double n0, double lambda,
                           const ViscousWall& wall, double dt, const std::vector<Vec<D>>& explicit_acceleration,
                           std::vector<Vec<D>>& viscous_acceleration);

  std::size_t unknowns() const { return particle_of_.size(); }  // of the last solve, this process's

 private:
  std::vector<std::uint8_t> stiff_;  // particle (owned and ghost) -> 1: an unknown
  std::vector<std::uint8_t> planes_;  // particle (owned and ghost) -> the axes of the planes of symmetry it lies on
  std::vector<std::uint8_t> near_stiff_;  // owned particle -> 1: an unknown or a fluid neighbour of one
  std::vector<std::uint32_t> particle_of_;  // unknown (row) -> owned particle
  std::vector<int> row_start_;
  std::vector<int> diagonal_at_;      // row -> its diagonal's place in the values
  // Per stored value: the particle (owned or ghost) whose unknown it multiplies, that unknown's id (the values of a
  // row are in id order), the axes its image negates (0: not an image).
  std::vector<std::uint32_t> entry_particle_;
  std::vector<ParticleId> entry_id_;
  std::vector<std::uint8_t> flip_;
  std::vector<std::array<double, 3>> own_image_;  // row -> the diagonal's share from its own images, per axis
  std::vector<std::uint8_t> on_planes_;  // row -> the axes of the planes of symmetry its particle lies on
  std::vector<double> values_;            // the rows, compressed
  std::vector<double> component_values_;  // of one velocity component, where images flip it
  std::vector<double> p_of_particle_;     // the solver's search direction at every particle (ghosts: their unknown's)

  // The values of velocity component d: values_ with the values of images flipped along d negated, and each row's own
  // images added to its diagonal; values_ itself without images.
  const std::vector<double>& values_of(int d, bool images);
};

inline const std::vector<double>& ImplicitViscosity::values_of(int d, bool images) {
  if (!images) return values_;
  component_values_ = values_;
  double* value = component_values_.data();
  for (std::size_t k = 0; k < flip_.size(); ++k) {
    if (flip_[k] >> d & 1) value[k] = -value[k];
    if (planes_[entry_particle_[k]] >> d & 1) value[k] = 0.0;  // a velocity held at zero
  }
  for (std::size_t r = 0; r < own_image_.size(); ++r) {
    const int first = row_start_[r], last = row_start_[r + 1];
    if (on_planes_[r] >> d & 1) {  // u_r,d = 0: the row of the identity
      std::fill(value + first, value + last, 0.0);
      value[diagonal_at_[r]] = 1.0;
      continue;
    }
    value[diagonal_at_[r]] += own_image_[r][d];
    if (on_planes_[r] == 0) continue;
    const double share = std::ldexp(1.0, -std::popcount(on_planes_[r]));
    for (int k = first; k < last; ++k) value[k] *= share;
  }
  return component_values_;
}

template <int D>
ViscousSolveReport ImplicitViscosity::solve(Domain<D>& domain, const NeighborList& nl, double re, double n0,
                                            double lambda, const ViscousWall& wall, double dt,
                                            const std::vector<Vec<D>>& explicit_acceleration,
                                            std::vector<Vec<D>>& viscous_acceleration) {
  Particles<D>& P = domain.particles;
  const std::size_t n = domain.owned_count();
  if (viscous_acceleration.size() < P.size()) viscous_acceleration.resize(P.size(), Vec<D>::Zero());
  // Every fluid particle starts at u + dt a, the u~ of those that are not unknowns.
  parallel_for(n, [&](std::size_t i) {
    if (P.kind[i] == Kind::fluid) P.velocity[i] += dt * explicit_acceleration[i];
  });
  domain.refresh({HaloField::velocity});
  // Unknowns: the stiff owned fluid particles (header); a ghost is its source's unknown. The same walk gives the
  // viscous acceleration at u + dt a, which is that at u~ wherever no unknown is near.
  const double stiff = stiff_row_number();
  stiff_.assign(P.size(), 0);
  parallel_for(n, [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    const ViscousRow<D> row = viscous_row<D>(i, P, nl, re, n0, lambda, wall, dt);
    stiff_[i] = row.number > stiff;
    viscous_acceleration[i] = row.acceleration;
  });
  domain.refresh_values(stiff_);
  // Rows in id order: a row's columns (sorted by id) and the solver's sums over rows then run in an order that does
  // not depend on where the particles are stored (fluid/domain.hpp).
  particle_of_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (stiff_[i]) particle_of_.push_back(static_cast<std::uint32_t>(i));
  std::sort(particle_of_.begin(), particle_of_.end(), [&](std::uint32_t a, std::uint32_t b) { return P.id[a] < P.id[b]; });
  const std::size_t rows = particle_of_.size();
  ViscousSolveReport report;
  if (domain.sum_over_processes(static_cast<std::int64_t>(rows)) == 0) return report;
  planes_.assign(P.size(), 0);
  for (std::size_t i = 0; i < n; ++i) planes_[i] = domain.planes_holding(i);
  domain.refresh_values(planes_);
  const double c = 2.0 * D / (lambda * n0);

  row_start_.assign(rows + 1, 0);
  parallel_for(rows, [&](std::size_t r) {
    const std::size_t i = particle_of_[r];
    int count = 1;
    auto fluid = [&](std::uint32_t j, double) { count += stiff_[j] && P.id[j] != P.id[i]; };
    for_each_viscous_coupling<D>(i, P, nl, re, wall, fluid, [](std::uint32_t, double) {});
    row_start_[r + 1] = count;
  });
  for (std::size_t r = 0; r < rows; ++r) row_start_[r + 1] += row_start_[r];
  const auto stored = static_cast<std::size_t>(row_start_[rows]);
  values_.assign(stored, 0.0);
  entry_particle_.assign(stored, 0);
  entry_id_.assign(stored, 0);
  flip_.assign(stored, 0);
  diagonal_at_.assign(rows, 0);
  own_image_.assign(rows, {0.0, 0.0, 0.0});
  on_planes_.assign(rows, 0);
  const std::size_t real = P.real_count();
  Eigen::Matrix<double, Eigen::Dynamic, D> rhs(rows, D), u(rows, D);

  parallel_for(rows, [&](std::size_t r) {
    const std::size_t i = particle_of_[r];
    Vec<D> b = P.density[i] * P.velocity[i];
    double diagonal = P.density[i];
    const int first = row_start_[r];
    int k = first;
    // Into the row in id order (after the values of the same id already in: a neighbour before its images).
    const auto insert = [&](std::uint32_t j, double value, std::uint8_t image_flip) {
      int at = k++;
      for (; at > first && entry_id_[at - 1] > P.id[j]; --at) {
        values_[at] = values_[at - 1];
        entry_particle_[at] = entry_particle_[at - 1];
        entry_id_[at] = entry_id_[at - 1];
        flip_[at] = flip_[at - 1];
      }
      values_[at] = value;
      entry_particle_[at] = j;
      entry_id_[at] = P.id[j];
      flip_[at] = image_flip;
      return at;
    };
    auto fluid = [&](std::uint32_t j, double coupling) {
      const double a = dt * c * coupling;
      diagonal += a;
      if (!stiff_[j]) {
        b += a * P.velocity[j];
        return;
      }
      const std::uint8_t image_flip = j < real ? 0 : P.ghost_flip[j - real];
      if (P.id[j] == P.id[i]) {  // its own image: -a u_image = -a sign u_i on the diagonal
        for (int d = 0; d < D; ++d) own_image_[r][d] -= (image_flip >> d & 1) ? -a : a;
        return;
      }
      insert(j, -a, image_flip);
    };
    auto wall_pair = [&](std::uint32_t j, double coupling) {
      const double a = dt * c * coupling;
      diagonal += a;
      b += a * P.velocity[j];
    };
    for_each_viscous_coupling<D>(i, P, nl, re, wall, fluid, wall_pair);
    diagonal_at_[r] = insert(static_cast<std::uint32_t>(i), diagonal, 0);
    on_planes_[r] = planes_[i];
    if (on_planes_[r] != 0) {  // its share of the modelled side (values_of); zero across the planes it lies on
      b *= std::ldexp(1.0, -std::popcount(on_planes_[r]));
      for (int d = 0; d < D; ++d)
        if (on_planes_[r] >> d & 1) b[d] = 0.0;
    }
    rhs.row(r) = b.transpose();
    u.row(r) = P.velocity[i].transpose();
  });

  // Whether an image enters any row (otherwise every component shares values_).
  const bool images = std::any_of(flip_.begin(), flip_.end(), [](std::uint8_t f) { return f != 0; }) ||
                      std::any_of(on_planes_.begin(), on_planes_.end(), [](std::uint8_t f) { return f != 0; }) ||
                      std::any_of(planes_.begin(), planes_.end(), [](std::uint8_t f) { return f != 0; }) ||
                      std::any_of(own_image_.begin(), own_image_.end(), [](const auto& o) {
                        return o[0] != 0.0 || o[1] != 0.0 || o[2] != 0.0;
                      });
  // Each component by conjugate gradients (fluid/conjugate_gradient.hpp): a row's product runs over its columns in id
  // order, the dot products are exact, so the solution does not depend on the particles' storage, the thread split or
  // the processes. The product reads every column's unknown through its particle: the search direction is carried to
  // the ghosts before each product.
  std::vector<double> inverse_diagonal(rows), b(rows), x(rows);
  p_of_particle_.assign(P.size(), 0.0);
  for (int d = 0; d < D; ++d) {
    const std::vector<double>& A = values_of(d, images);
    parallel_for(rows, [&](std::size_t r) {
      const double diagonal = A[static_cast<std::size_t>(diagonal_at_[r])];
      inverse_diagonal[r] = diagonal != 0.0 ? 1.0 / diagonal : 1.0;
      b[r] = rhs(static_cast<Eigen::Index>(r), d);
      x[r] = u(static_cast<Eigen::Index>(r), d);
    });
    const auto product = [&](const std::vector<double>& p, std::vector<double>& y) {
      parallel_for(rows, [&](std::size_t r) { p_of_particle_[particle_of_[r]] = p[r]; });
      domain.refresh_values(p_of_particle_);
      parallel_for(rows, [&](std::size_t r) {
        double sum = 0.0;
        for (int k = row_start_[r]; k < row_start_[r + 1]; ++k)
          sum += A[static_cast<std::size_t>(k)] * p_of_particle_[entry_particle_[static_cast<std::size_t>(k)]];
        y[r] = sum;
      });
    };
    const auto combine = [&domain](ExactSum* sums, std::size_t count) { domain.combine(sums, count); };
    const ConjugateGradientReport cg =
        conjugate_gradient(product, inverse_diagonal, b, x, tolerance, max_iterations, combine);
    parallel_for(rows, [&](std::size_t r) { u(static_cast<Eigen::Index>(r), d) = x[r]; });
    report.iterations = std::max(report.iterations, cg.iterations);
    report.residual = std::max(report.residual, cg.error);
    report.converged = report.converged && cg.converged;
  }
  parallel_for(rows, [&](std::size_t r) { P.velocity[particle_of_[r]] = u.row(r).transpose(); });
  domain.refresh({HaloField::velocity});

  // The viscous acceleration again where u~ changed: at the unknowns and every fluid particle that lists one (the
  // lists are symmetric, images included: a superset of the neighbours within re).
  near_stiff_.assign(n, 0);
  parallel_for(n, [&](std::size_t q) {
    if (P.kind[q] != Kind::fluid) return;
    bool near = stiff_[q] != 0;
    for (const std::uint32_t* l = nl.begin(q); l != nl.end(q) && !near; ++l) near = stiff_[*l] != 0;
    near_stiff_[q] = near;
  });
  parallel_for(n, [&](std::size_t i) {
    if (near_stiff_[i]) viscous_acceleration[i] = viscous_row<D>(i, P, nl, re, n0, lambda, wall, dt).acceleration;
  });
  return report;
}

}  // namespace slide
