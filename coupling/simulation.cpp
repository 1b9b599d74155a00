#include "coupling/simulation.hpp"

#include "fluid/corrective_matrix.hpp"

#include <algorithm>
#include <random>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "fluid/artificial_viscosity.hpp"
#include "fluid/basal_friction.hpp"
#include "fluid/collision.hpp"
#include "fluid/confining_pressure.hpp"
#include "fluid/number_density.hpp"
#include "fluid/parallel.hpp"
#include "fluid/periodic.hpp"
#include "coupling/position_text.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/wall_pressure.hpp"

namespace slide {

template <int D>
void Simulation<D>::check_periodic_setup() const {
  const PeriodicX& period = *options.periodic_x;
  // A body's force is the sum over its boundary particles' fluid neighbours; ghost images of the body's particles
  // and of the fluid would count pairs across the period twice (and a body is not periodic), so refuse.
  if (bodies_)
    throw std::invalid_argument("periodic_x cannot be combined with rigid bodies: the fluid-body force exchange would "
                                "count ghost images twice");
  if (!(period.x_max > period.x_min))
    throw std::invalid_argument("periodic_x: x_max must exceed x_min");
  if (!(period.length() >= 2.0 * list_radius()))
    throw std::invalid_argument("periodic_x: the period (" + std::to_string(period.length()) +
                                " m) must be at least twice the kernel radius plus the neighbour skin (" +
                                std::to_string(2.0 * list_radius()) + " m)");
  const auto& P = domain_.particles;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const double x = P.position[i][0];
    if (P.kind[i] != Kind::fluid && !(x >= period.x_min && x < period.x_max))
      throw std::invalid_argument("periodic_x: boundary particle " + std::to_string(P.id[i]) + " at x = " +
                                  std::to_string(x) + " lies outside the period [" + std::to_string(period.x_min) +
                                  ", " + std::to_string(period.x_max) +
                                  "): walls along a periodic channel must cover the period exactly once");
  }
}

// Planes of symmetry (options.mirrors): every boundary particle on their modelled side, two planes on one axis far enough
// apart that a particle is near one of them at most, and none along a periodic x.
template <int D>
void Simulation<D>::check_mirror_setup() const {
  const auto& M = options.mirrors;
  if (M.empty()) return;
  for (std::size_t k = 0; k < M.size(); ++k) {
    if (M[k].axis < 0 || M[k].axis >= D) throw std::invalid_argument("a plane of symmetry's axis is not one of the scene's");
    if (options.periodic_x && M[k].axis == 0)
      throw std::invalid_argument("a plane of symmetry across x cannot be combined with periodic_x");
    for (std::size_t l = 0; l < k; ++l)
      if (M[l].axis == M[k].axis && !(std::abs(M[l].at - M[k].at) >= 2.0 * list_radius()))
        throw std::invalid_argument("two planes of symmetry across " + std::string(1, "xyz"[M[k].axis]) +
                                    " stand closer than twice the kernel radius plus the neighbour skin (" +
                                    std::to_string(2.0 * list_radius()) + " m)");
    const auto& P = domain_.particles;
    for (std::size_t i = 0; i < P.real_count(); ++i)  // fluid that crossed comes back at the next rebuild
      if (P.kind[i] != Kind::fluid && M[k].inside(P.position[i][M[k].axis]) < -1e-9 * options.dp)
        throw std::invalid_argument("boundary particle " + std::to_string(P.id[i]) + " lies beyond a plane of symmetry (" +
                                    std::string(1, "xyz"[M[k].axis]) + " = " + std::to_string(M[k].at) + ")");
  }
}

template <int D>
void Simulation<D>::initialise() {
  const double dp = options.dp;
  lattice = lattice_constants<D>(dp, re(), options.lattice);
  rheology_ = false;
  for (const auto& ph : phases) rheology_ = rheology_ || !std::holds_alternative<Newtonian>(ph.rheology);
  basal_friction_ = false;
  for (const auto& ph : phases) basal_friction_ = basal_friction_ || std::isfinite(ph.basal_friction);
  // The water's surface serves the frictional strengths' pore pressure and the water under bodies resting on walls.
  bool frictional = basal_friction_ || bodies_ != nullptr;
  for (const auto& ph : phases) frictional = frictional || depends_on_pressure(ph.rheology);
  pore_water_ = frictional && options.pore_pressure == PorePressureModel::hydrostatic && !phases.empty() &&
                std::holds_alternative<Newtonian>(phases[0].rheology) && options.gravity.norm() > 0.0;
  eos = EquationOfState(lattice.n0, options.sound_speed, options.gamma);
  Vec<D> grid_lo = options.domain_lo, grid_hi = options.domain_hi;
  domain_.set_ghost_layout({options.periodic_x, options.mirrors});
  if (options.periodic_x) {
    check_periodic_setup();
    // The grid also covers the ghost layers beyond the period's ends.
    grid_lo[0] = std::min(grid_lo[0], options.periodic_x->x_min - list_radius());
    grid_hi[0] = std::max(grid_hi[0], options.periodic_x->x_max + list_radius());
  }
  check_mirror_setup();
  for (const MirrorPlane& m : options.mirrors) {  // and the mirror images' layers beyond the planes
    grid_lo[m.axis] = std::min(grid_lo[m.axis], m.at - list_radius());
    grid_hi[m.axis] = std::max(grid_hi[m.axis], m.at + list_radius());
  }
  grid_ = NeighborGrid<D>(grid_lo, grid_hi, list_radius());
  if (observers_copy_) return;  // its particles and their fields come from the running simulation
  if (domain_.distributed()) prepare_processes();
  scratch_.assign(domain_.particles.size(), Vec<D>::Zero());
  predictor_acceleration_.clear();  // sized by the semi-implicit stage, the only one that uses it
  if (bodies_) bodies_->place_particles(domain_.particles, time_);
  update_neighbors(true);
  scratch_.resize(domain_.particles.size());  // a share of the scene made whole keeps no more than its own
  scratch_.shrink_to_fit();
  compute_pressure();
  update_water_surface();
}

// Several processes (fluid/domain.hpp): what runs across them today, and the depth of their ghost layers.
template <int D>
void Simulation<D>::check_processes(int processes) const {
  if (processes <= 1) return;
  if (static_cast<std::size_t>(processes) > grid_.total_cells())
    throw TooManyProcesses(fmt::format("{} processes for a neighbour grid of {} cells (each process needs at least "
                                       "one): start fewer processes", processes, grid_.total_cells()));
}

template <int D>
void Simulation<D>::prepare_processes() {
  check_processes(domain_.communicator()->size());
  domain_.set_rebalance_imbalance(options.rebalance_imbalance);
  // A boundary particle's mirror image lies twice its depth in front of it, and the fluid around the image must be
  // here (fluid/wall_pressure.hpp, mirror_fill: the cells around the image's cell).
  const auto& P = domain_.particles;
  const double deepest = domain_.max_over_owned(0.0, [&](std::size_t i) {
    return P.kind[i] == Kind::fluid ? 0.0 : P.wall_depth[i];
  });
  int reach = 1;
  if (options.wall_pressure == WallPressure::mirror)
    reach = 1 + static_cast<int>(std::ceil(2.0 * deepest / grid_.cell_size()));
  domain_.set_halo_reach(reach);
}

// The re-sort that shares the particles is made at the positions of the last re-sort (a scene just built or settled:
// the present ones; a resumed run: the checkpoint's), so that every process's particles, ghosts and neighbour lists
// are those the run would have had on these processes since then; then the present positions go back in place.
template <int D>
void Simulation<D>::distribute(std::shared_ptr<const Communicator> comm) {
  if (domain_.distributed()) return;  // shared since its build
  domain_.set_communicator(std::move(comm));
  if (!domain_.distributed()) return;
  prepare_processes();
  // The particles that left before (a resumed run's) are the first process's to report, once.
  if (domain_.communicator()->rank() > 0) left_the_domain_.clear();
  auto& P = domain_.particles;
  // The corrected gradient's matrices of the last pressure stage go along too (the semi-implicit predictor reads them).
  const bool correction = correction_current_;
  std::vector<Vec<D>> now_by_id(P.id_end());
  std::vector<Mat<D>> correction_by_id(correction ? P.id_end() : 0);
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    now_by_id[P.id[i]] = P.position[i];
    P.position[i] = position_at_build_[i];
    if (correction) correction_by_id[P.id[i]] = P.gradient_correction[i];
  }
  update_neighbors(true);
  --rebuilds_;  // a re-sort one process does not make: run.json counts as one process
  for (std::size_t i = 0; i < P.real_count(); ++i) P.position[i] = now_by_id[P.id[i]];
  domain_.refresh({HaloField::motion, HaloField::number_density, HaloField::pressure, HaloField::viscosity,
                   HaloField::wall_fraction, HaloField::wall_fill, HaloField::wall_normal});
  if (correction) {
    P.gradient_correction.resize(P.size());
    for (std::size_t i = 0; i < P.real_count(); ++i) P.gradient_correction[i] = correction_by_id[P.id[i]];
    domain_.refresh({HaloField::gradient_correction});
    correction_current_ = true;
  }
  scratch_.resize(P.size(), Vec<D>::Zero());
}

template <int D>
void Simulation<D>::restart_at_rest() {
  auto& P = domain_.particles;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    P.velocity[i] = Vec<D>::Zero();
    P.acceleration[i] = Vec<D>::Zero();
    P.wall_fraction[i] = 1.0;  // at rest nothing slides
  }
  time_ = 0.0;
  step_count_ = 0;
  limit_counts_ = {};
  largest_number_density_ratio_ = 1.0;
  largest_number_density_ratio_time_ = 0.0;
  viscous_solves_ = {};
  left_the_domain_.clear();  // the run's own account starts at t = 0 (a settled start refuses water that left)
  initialise();
}

template <int D>
void Simulation<D>::refresh_moved_ghosts() {
  domain_.refresh({HaloField::motion});
}

template <int D>
void Simulation<D>::remove_particles(const std::vector<ParticleId>& ids) {
  domain_.drop_ghosts();
  auto& P = domain_.particles;
  const std::size_t removed_before = P.removed_count;
  P.remove_keeping_ids([&](std::size_t i) { return std::binary_search(ids.begin(), ids.end(), P.id[i]); });
  for (std::size_t i = 0; i < P.size(); ++i)
    P.id[i] -= static_cast<ParticleId>(std::lower_bound(ids.begin(), ids.end(), P.id[i]) - ids.begin());
  P.removed_count = removed_before;
}

template <int D>
void Simulation<D>::update_neighbors(bool force) {
  auto& x = domain_.particles.position;
  const double half_skin = 0.5 * options.skin_over_dp * options.dp;
  if (!force) {
    // Ghosts move with their sources: the real particles decide.
    const double moved2 = domain_.max_over_owned(0.0, [&](std::size_t i) {
      return distance_squared<D>(x[i], position_at_build_[i]);
    });
    if (moved2 < half_skin * half_skin) return;
  }
  // Drop the ghosts and bring the real particles back into the period before sorting them.
  domain_.drop_ghosts();
  domain_.bring_inside();
  domain_.redistribute(grid_);  // several processes: each its own cells' particles
  // Re-sort particles by cell so that neighbours are near each other in memory, then bin and list again. Within a
  // cell by id: every neighbour sum then runs in an order that is the same whatever the particles' storage order
  // (fluid/neighbor_grid.hpp).
  const auto key = [&P = domain_.particles](std::uint32_t j) { return P.order_key(j); };
  grid_.bin(x, key);
  domain_.particles.reorder(grid_.sorted_indices(), scratch_);  // scratch_ is free between steps
  if (storage_shuffle_seed_) shuffle_owned_particles();
  // Fresh ghosts behind the sorted real domain_.particles; they are binned and found as neighbours, but need no list of
  // their own (every stage computes real particles only and refreshes the ghosts).
  if (domain_.make_ghosts(list_radius(), grid_) || storage_shuffle_seed_) {
    scratch_.resize(domain_.particles.size(), Vec<D>::Zero());
    grid_.bin(x, key);
  } else {
    grid_.follow_reorder();  // the binning of the sorted domain_.particles, known without binning them again
  }
  build_neighbor_list(grid_, x, list_radius(), list_, domain_.particles.real_count());
  const std::size_t listed = list_.total();
  if (most_listed_ == 0) listed_at_first_build_ = listed, held_at_first_build_ = domain_.particles.size();
  most_listed_ = std::max(most_listed_, listed);
  most_held_ = std::max(most_held_, domain_.particles.size());
  pair_weights_.forget();  // of the list before
  position_at_build_ = x;
  ++rebuilds_;
  correction_current_ = false;  // of the order before
}

template <int D>
void Simulation<D>::shuffle_owned_particles() {
  std::vector<std::uint32_t> order(domain_.particles.real_count());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(*storage_shuffle_seed_ + static_cast<std::uint64_t>(rebuilds_)));
  domain_.particles.reorder(order, scratch_);
}

// Periodic: each sub-stage computes the real domain_.particles, and its result is copied into the ghosts before the next
// reads it (a ghost's own neighbourhood is cut off at the outer edge of the ghost layer, so a ghost never computes).
template <int D>
void Simulation<D>::compute_pressure() {
  auto& P = domain_.particles;
  const std::size_t n = P.real_count();
  const double r_e = re();
  using WP = WallPressure;
  if (options.wall_pressure == WP::mirror) {
    // Each boundary particle keeps its image's fluid neighbours for its pressure below, at these same positions.
    image_neighbours_.take(n, [&](std::size_t i, auto&& keep) {
      if (P.kind[i] == Kind::fluid) return false;
      P.wall_fill[i] = mirror_fill<D>(i, P, grid_, list_, options.dp, keep);
      return true;
    });
    domain_.refresh({HaloField::wall_fill});
  }
  // Fluid particles keep their pairs' factors for the pressure gradient at these same positions
  // (correct_with_pressure_gradient), where the model reads them.
  const PairFactor factor = kept_pair_factor(options.gradient);
  pair_weights_.shape_like(list_);
  const std::vector<double>* fill = options.wall_pressure == WP::mirror ? &P.wall_fill : nullptr;
  const double surface_n = options.free_surface_beta * lattice.n0;
  const bool corrected = options.gradient == GradientModel::corrected;
  const bool half_layer = options.surface_pressure == SurfacePressure::half_layer;
  const double gravity = options.gravity.norm(), layer = row_spacing(options.lattice, options.dp);
  if (corrected) P.gradient_correction.resize(P.size());
  // A fluid particle's pressure follows from its own number density (seed eq. 7), and the corrected gradient's
  // matrix from the pair factors just kept (boundary particles keep the identity): in the same pass.
  parallel_for(n, [&](std::size_t i) {
    const bool fluid = P.kind[i] == Kind::fluid;
    Mat<D> moment;
    const double n_i = fluid ? number_density_keeping_weights<D>(i, P.position, fill, list_, r_e,
                                                                 pair_weights_.of(list_, i), factor,
                                                                 corrected ? &moment : nullptr)
                       : fill ? weighted_number_density_of<D>(i, P.position, *fill, list_, r_e)
                              : number_density_of<D>(i, P.position, list_, r_e);
    P.number_density[i] = n_i;
    if (corrected)  // I for a boundary or free-surface particle, as corrective_matrix
      P.gradient_correction[i] = fluid && n_i >= surface_n ? faded_inverse<D>(moment, lattice.kappa * lattice.n0)
                                                           : Mat<D>::Identity();
    if (!fluid) return;
    double p = n_i >= surface_n ? eos.pressure(n_i, P.density[i])
               : half_layer ? half_layer_pressure(P.density[i], gravity, layer)
                            : 0.0;  // extrapolated below, from the bulk's final pressures
    if (options.clamp_negative_pressure && p < 0.0) p = 0.0;
    P.pressure[i] = p;
  });
  pair_weights_.mark_taken_at(step_count_, factor);
  domain_.refresh({HaloField::number_density, HaloField::pressure});
  if (corrected) {
    domain_.refresh({HaloField::gradient_correction});
    correction_current_ = true;
  }
  if (options.surface_pressure == SurfacePressure::extrapolated) {
    // Surface particles read only bulk ones, whose pressures are final: one pass, in any order.
    const auto is_bulk = [&](std::uint32_t b) { return P.number_density[b] >= surface_n; };
    parallel_for(n, [&](std::size_t i) {
      if (P.kind[i] == Kind::fluid && P.number_density[i] < surface_n)
        P.pressure[i] = extrapolated_surface_pressure<D>(i, P, list_, r_e, options.gravity, is_bulk);
    });
    domain_.refresh({HaloField::pressure});
  }
  // boundary pressure below reads the fluid's, ghosts' included
  // The head between a boundary particle and the fluid follows g - a_w: a wall that accelerates into the water
  // pushes harder (Adami, Hu & Adams 2012, eq. 27). Fixed walls have a_w = 0; body particles carry their body's
  // rigid acceleration (coupling/rigid_bodies.hpp).
  const auto head_acceleration = [&](std::size_t i) -> Vec<D> { return options.gravity - P.acceleration[i]; };
  const auto set_boundary_pressure = [&](std::size_t i, double p) {
    if (options.clamp_negative_pressure && p < 0.0) p = 0.0;
    P.pressure[i] = p;
  };
  if (options.wall_pressure == WP::extrapolated) {
    parallel_for(n, [&](std::size_t i) {
      if (P.kind[i] == Kind::fluid) return;
      set_boundary_pressure(i, extrapolated_wall_pressure<D>(i, P, list_, r_e, head_acceleration(i)));
    });
  } else {
    image_neighbours_.for_each([&](std::size_t i, const ImageNeighbour* begin, const ImageNeighbour* end) {
      set_boundary_pressure(i, mirror_wall_pressure<D>(i, P, begin, end, head_acceleration(i)));
    });
  }
  domain_.refresh({HaloField::pressure});
}

// The corrected gradient's matrices at the particles' present positions (fluid/corrective_matrix.hpp); identity
// matrices for the other models are never read.
template <int D>
void Simulation<D>::update_gradient_correction() {
  if (options.gradient != GradientModel::corrected) return;
  auto& P = domain_.particles;
  const double surface_n = options.free_surface_beta * lattice.n0, r_e = re();
  P.gradient_correction.resize(P.size());
  parallel_for(P.real_count(), [&](std::size_t i) {
    P.gradient_correction[i] = corrective_matrix<D>(i, P, list_, r_e, lattice.n0, lattice.kappa, surface_n);
  });
  domain_.refresh({HaloField::gradient_correction});
  correction_current_ = true;
}

template <int D>
double Simulation<D>::max_fluid_speed() const {
  const auto& P = domain_.particles;
  return std::sqrt(domain_.max_over_owned(0.0, [&](std::size_t i) {
    return P.kind[i] == Kind::fluid ? P.velocity[i].squaredNorm() : 0.0;
  }));
}

template <int D>
std::pair<double, TimeStepLimit> Simulation<D>::allowed_time_step() const {
  const auto& P = domain_.particles;
  const double dp = options.dp;
  // Moving boundaries count in the CFL limit: a slide faster than the water around it must not cross more than a
  // fraction of a spacing per step either (fixed walls have zero velocity).
  // So do they in the force limit: body particles carry their body's rigid acceleration (a slide hitting the slope
  // or the water decelerates hard), fixed walls zero. The three largest in one pass.
  const auto [u2_max, a2_max, nu_max] =
      domain_.template max_each_over_owned<3>({0.0, 0.0, 0.0}, [&](std::size_t i) -> std::array<double, 3> {
        return {P.velocity[i].squaredNorm(), P.acceleration[i].squaredNorm(),
                P.kind[i] == Kind::fluid ? P.viscosity[i] / P.density[i] : 0.0};
      });
  const double u_max = std::sqrt(u2_max), a_max = std::sqrt(a2_max);
  std::pair<double, TimeStepLimit> best{options.dt_max, TimeStepLimit::dt_max};
  auto consider = [&](double dt, TimeStepLimit l) {
    if (dt < best.first) best = {dt, l};
  };
  consider(options.cfl * dp / (options.sound_speed + u_max), TimeStepLimit::cfl);
  if (nu_max > 0.0 && options.viscous_scheme == ViscousScheme::explicit_) consider(options.viscous_number * dp * dp / nu_max, TimeStepLimit::viscous);
  if (a_max > 0.0) consider(options.force_number * std::sqrt(dp / a_max), TimeStepLimit::force);
  return best;
}

template <int D>
std::optional<Instability> Simulation<D>::step(double dt, TimeStepLimit limit) {
  update_neighbors(false);
  const bool walls_checked = !wall_crossing.empty();
  if (walls_checked) {
    position_at_step_start_.resize(domain_.particles.real_count());
    parallel_for(domain_.particles.real_count(), [&](std::size_t i) { position_at_step_start_[i] = domain_.particles.position[i]; });
  }
  update_water_surface();
  update_viscosity(dt);
  predict_with_viscosity_and_gravity(dt);
  compute_pressure();  // at the predicted positions
  correct_with_pressure_gradient(dt);
  collide(dt);
  move_bodies(dt);
  time_ += dt;
  ++step_count_;
  ++limit_counts_[static_cast<int>(limit)];
  // What the end of a step looks for, in one pass (each was a pass of its own, 1.5-2 % of the step each).
  const auto& P = domain_.particles;
  const auto [crossed, worst, densest, left] = domain_.template max_each_over_owned<4>(
      {0.0, 0.0, 0.0, 0.0}, [&](std::size_t i) -> std::array<double, 4> {
        return {walls_checked && face_crossed(i) >= 0 ? 1.0 : 0.0, static_cast<double>(problem_code(i)),
                P.kind[i] == Kind::fluid ? P.number_density[i] : 0.0, outside_domain(i) ? 1.0 : 0.0};
      });
  if (crossed > 0.0) return wall_crossing_report();
  record_largest_compression(densest);  // a collapse reported next is the run's largest compression
  // Checked before the leavers go, so that a particle that blew up on its way out is reported, not counted.
  if (worst > 0.0) return problem_report(static_cast<int>(worst));
  if (left > 0.0) remove_particles_that_left();
  return std::nullopt;
}

// The wall face fluid particle i's move in this step went through (fluid/wall_crossing.hpp), or -1.
template <int D>
int Simulation<D>::face_crossed(std::size_t i) const {
  const auto& P = domain_.particles;
  if (P.kind[i] != Kind::fluid || i >= position_at_step_start_.size()) return -1;
  return wall_crossing.crossed(position_at_step_start_[i], P.position[i]);
}

// The crossing of lowest id (whatever the thread and process count), as an instability.
template <int D>
std::optional<Instability> Simulation<D>::wall_crossing_report() const {
  const auto& P = domain_.particles;
  // Where it started and ended, and the face (every process knows the faces).
  const auto found = domain_.template lowest_id_where<2 * D + 1>(
      [&](std::size_t i) { return face_crossed(i) >= 0; },
      [&](std::size_t i) {
        std::array<double, 2 * D + 1> v;
        for (int k = 0; k < D; ++k) {
          v[k] = position_at_step_start_[i][k];
          v[D + k] = P.position[i][k];
        }
        v[2 * D] = face_crossed(i);
        return v;
      });
  if (!found) return std::nullopt;
  const auto& [id, v] = *found;
  Vec<D> from, to;
  for (int k = 0; k < D; ++k) {
    from[k] = v[k];
    to[k] = v[D + k];
  }
  const WallFace<D>& f = wall_crossing.face(static_cast<int>(v[2 * D]));
  Instability s;
  s.time = time_;
  s.step = step_count_;
  s.particle = id;
  s.position.assign(to.data(), to.data() + D);
  std::string face;
  for (const Vec<D>& c : f.corner) face += (face.empty() ? "" : " - ") + position_text<D>(c);
  s.reason = fmt::format("passed through a wall: it moved from {} to {} in one step, past the back of the wall face {}",
                         position_text<D>(from), position_text<D>(to), face);
  return s;
}

// A fluid particle outside the domain's bounds (along a periodic x, only the other axes bound it). A NaN coordinate
// compares false both ways: it is not "outside", and the check reports it.
template <int D>
bool Simulation<D>::outside_domain(std::size_t i) const {
  const auto& P = domain_.particles;
  if (P.kind[i] != Kind::fluid) return false;
  const Vec<D>& x = P.position[i];
  bool out = false;
  for (int k = options.periodic_x ? 1 : 0; k < D; ++k)
    out = out || x[k] < options.domain_lo[k] || x[k] > options.domain_hi[k];
  return out;
}

// Fluid particles outside the domain's bounds left through an open side (a move through a wall was reported before
// this): they are recorded and taken out, and the neighbour list is built afresh without them.
template <int D>
void Simulation<D>::remove_particles_that_left() {
  auto& P = domain_.particles;
  const std::size_t n = P.real_count();
  std::vector<std::size_t> leaving;
  for (std::size_t i = 0; i < n; ++i)
    if (outside_domain(i)) leaving.push_back(i);
  // Several processes: every one rebuilds (a collective), whether any of its own left or not.
  if (leaving.empty() && !domain_.distributed()) return;
  std::sort(leaving.begin(), leaving.end(), [&](std::size_t a, std::size_t b) { return P.id[a] < P.id[b]; });
  for (const std::size_t i : leaving)
    left_the_domain_.push_back({P.id[i], time_, std::vector<double>(P.position[i].data(), P.position[i].data() + D)});
  std::vector<bool> drop(n, false);
  for (const std::size_t i : leaving) drop[i] = true;
  domain_.drop_ghosts();
  P.remove_keeping_ids([&](std::size_t i) { return i < n && drop[i]; });
  update_neighbors(true);
}

// n_max: the largest number density of any fluid particle after the step.
template <int D>
void Simulation<D>::record_largest_compression(double n_max) {
  const double ratio = n_max / lattice.n0;
  if (ratio > largest_number_density_ratio_) {
    largest_number_density_ratio_ = ratio;
    largest_number_density_ratio_time_ = time_;
  }
}

// Rheology: each fluid particle's viscosity from its phase's model at its shear rate (fluid/strain_rate.hpp, walls
// mirrored as in the viscous term) and its pressure, both of the start of the step (the viscosity is lagged).
// Basal friction: then, for a phase with a Coulomb basal friction, the fraction of that viscosity its wall pairs use
// (fluid/basal_friction.hpp), from the same start-of-step velocities and pressures (lagged alike).
template <int D>
void Simulation<D>::update_viscosity(double dt) {
  if (!rheology_ && !basal_friction_) return;
  const PorePressureField<D> pore = pore_pressure_field();
  auto& P = domain_.particles;
  const std::size_t n = P.real_count();
  const double r_e = re();
  if (rheology_) {
    parallel_for(n, [&](std::size_t i) {
      if (P.kind[i] != Kind::fluid) return;
      const Rheology& model = phases[P.phase[i]].rheology;
      if (std::holds_alternative<Newtonian>(model)) return;
      if (rheology_suspended_) {
        P.viscosity[i] = settling_viscosity(model);
        return;
      }
      const double rate = shear_rate<D>(i, P, list_, r_e, lattice.n0, options.viscous_wall());
      const double pressure = depends_on_pressure(model)
                                  ? effective_pressure(confining_pressure<D>(i, P, list_, r_e), pore.at(P.position[i]))
                                  : P.pressure[i];
      P.viscosity[i] = effective_viscosity(model, rate, pressure);
    });
    domain_.refresh({HaloField::viscosity});
  }
  if (basal_friction_ && options.wall_slip == WallSlip::no_slip) {
    const ViscousWall wall = options.viscous_wall();
    parallel_for(n, [&](std::size_t i) {
      if (P.kind[i] != Kind::fluid) return;
      const double mu_b = phases[P.phase[i]].basal_friction;
      if (!std::isfinite(mu_b)) return;
      const WallShear s = wall_shear<D>(i, P, list_, r_e, wall.min_distance, options.gravity, pore, dt);
      P.wall_fraction[i] = coulomb_wall_fraction(P.viscosity[i], mu_b, s.normal_stress, s.rate);
    });
    domain_.refresh({HaloField::wall_fraction});
  }
}

// The water's surface, from the first phase's particles where they are (fluid/water_surface.hpp): at the start of
// each step, for the pore pressure of the step's frictional strengths (lagged like the viscosity) and the water
// under bodies resting on walls (coupling/dry_face_pressure.hpp).
template <int D>
void Simulation<D>::update_water_surface() {
  if (!pore_water_) return;
  const auto& P = domain_.particles;
  water_surface_.build(P, options.gravity, options.dp, [&](std::size_t i) { return P.phase[i] == 0; },
                       domain_.distributed() ? domain_.communicator() : nullptr);
}

template <int D>
PorePressureField<D> Simulation<D>::pore_pressure_field() const {
  if (!pore_water_) return {};
  return {phases[0].density_kg_m3, options.gravity.norm(), &water_surface_};
}

// Viscosity and gravity give the predicted velocity and position (fluid only). Explicitly, the viscous term is
// evaluated at the velocities of the start of the step; semi-implicitly (fluid/implicit_viscosity.hpp) at the
// solution u~ of the implicit system. Either way the same pair terms then update the fluid and, for body domain_.particles,
// go to their bodies (before the positions move), so momentum is exchanged exactly whatever the solver's tolerance:
// u* = u + dt (a + a_visc(u~)) differs from u~ only by the solver's residual and the pressure gradient's share.
template <int D>
void Simulation<D>::predict_with_viscosity_and_gravity(double dt) {
  auto& P = domain_.particles;
  const std::size_t n = P.real_count();  // ghosts are copied from their sources at the end
  const double r_e = re();
  const bool implicit = options.viscous_scheme == ViscousScheme::implicit;
  if (implicit) {
    // Explicit accelerations first: gravity and artificial viscosity. The viscous solve is given them together with
    // the pressure gradient of the last step, -grad p / rho at the pressures of the start of the step (an
    // incremental pressure-correction predictor: Goda 1979, J. Comput. Phys. 30, 76-95; van Kan 1986, SIAM J. Sci.
    // Stat. Comput. 7, 870-891), so that it sees the motion the step will make: none in water or sediment at rest,
    // the driving force's in a channel. Why: given gravity alone, the solve saw each step's fall under gravity
    // (which the pressure then undoes) and a no-slip wall resisted it; with a yield stress's viscosity at rest (up to
    // 1e6 Pa s) the walls carried the sediment's weight by viscosity instead of pressure, and a Mohr-Coulomb layer
    // at rest rose off its floor and lost half its pressure in 0.1 s (measured). Given no acceleration at all, a
    // channel driven by a body force f was offset by dt f (+0.4 % of the Bingham channel's centreline, measured).
    // The step itself applies only a (below) and then the new pressure's gradient, as the explicit scheme does.
    const GradientModel gradient = options.gradient;
    // The matrices of the last pressure stage, one step's motion old (this is the predictor's estimate of the step's
    // pressure gradient, not the one applied), unless the particles were re-sorted or restored since, or there was
    // none: with a pass here and one in the pressure stage, the matrices took 40 % of a sediment step (perf, issue 29).
    if (!correction_current_) update_gradient_correction();
    // Only this stage needs it (16 bytes a particle otherwise held for nothing); the solve reads real fluid entries.
    if (predictor_acceleration_.size() != P.size()) predictor_acceleration_.assign(P.size(), Vec<D>::Zero());
    parallel_for(n, [&](std::size_t i) {
      if (P.kind[i] != Kind::fluid) return;
      Vec<D> a = options.gravity;
      if (options.artificial_viscosity > 0.0)
        a += artificial_viscous_acceleration<D>(i, P, list_, r_e, lattice.n0, options.artificial_viscosity,
                                                options.sound_speed, options.dp);
      P.acceleration[i] = a;
      predictor_acceleration_[i] =
          a - pressure_gradient<D>(gradient, i, P, list_, r_e, lattice.n0, lattice.kappa) / P.density[i];
    });
    start_velocity_.assign(P.velocity.begin(), P.velocity.end());
    implicit_viscosity_.tolerance = options.implicit_tolerance;
    // u~ (ghosts included) and, in scratch_, the viscous acceleration at u~ of every fluid particle.
    last_viscous_solve_ = implicit_viscosity_.solve<D>(domain_, list_, r_e, lattice.n0, lattice.lambda, options.viscous_wall(),
                                                       dt, predictor_acceleration_, scratch_);
    record(last_viscous_solve_);
  } else {
    parallel_for(n, [&](std::size_t i) {
      if (P.kind[i] != Kind::fluid) return;
      Vec<D> a = viscous_acceleration<D>(i, P, list_, r_e, lattice.n0, lattice.lambda, options.viscous_wall());
      if (options.artificial_viscosity > 0.0)
        a += artificial_viscous_acceleration<D>(i, P, list_, r_e, lattice.n0, options.artificial_viscosity,
                                                options.sound_speed, options.dp);
      P.acceleration[i] = a + options.gravity;
    });
  }
  if (bodies_)
    bodies_->add_viscous_forces(domain_, list_, r_e, lattice.n0, lattice.lambda, options.viscous_wall(), particle_volume());
  parallel_for(n, [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    if (implicit) {
      P.acceleration[i] += scratch_[i];
      P.velocity[i] = start_velocity_[i];
    }
    P.velocity[i] += dt * P.acceleration[i];
    P.position[i] += dt * P.velocity[i];
  });
  domain_.refresh({HaloField::motion});
}

template <int D>
void Simulation<D>::record(const ViscousSolveReport& r) {
  auto& s = viscous_solves_;
  ++s.solves;
  s.iterations += r.iterations;
  s.most_iterations = std::max(s.most_iterations, r.iterations);
  s.largest_residual = std::max(s.largest_residual, r.residual);
  if (!r.converged) ++s.unconverged;
}

// Pressure-gradient correction of velocity and position (and the settling's damping, when on).
template <int D>
void Simulation<D>::correct_with_pressure_gradient(double dt) {
  auto& P = domain_.particles;
  const double r_e = re();
  const GradientModel model = options.gradient;
  const double damping = options.velocity_damping_rate > 0.0 ? std::exp(-dt * options.velocity_damping_rate) : 1.0;
  const std::size_t n = P.real_count();
  // Taken by compute_pressure in this step, at these positions (no stage moves a particle in between).
  const bool factors_taken = pair_weights_.taken_at(step_count_, kept_pair_factor(model));
  parallel_for(n, [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    const double* f = factors_taken ? pair_weights_.of(list_, i) : nullptr;
    scratch_[i] = (-1.0 / P.density[i]) * pressure_gradient<D>(model, i, P, list_, r_e, lattice.n0, lattice.kappa, f);
  });
  if (bodies_) {
    bodies_->add_pressure_forces(domain_, list_, model, r_e, lattice.n0, lattice.kappa, particle_volume());
    bodies_->add_dry_face_pressure(domain_, grid_, pore_pressure_field(), options.dp);
  }
  parallel_for(n, [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    P.velocity[i] += dt * scratch_[i];
    P.position[i] += (dt * dt) * scratch_[i];
    if (damping != 1.0) P.velocity[i] *= damping;
    P.acceleration[i] += scratch_[i];
  });
  domain_.refresh({HaloField::motion});
}

// Collisions between particles that came too close (fluid/collision.hpp).
template <int D>
void Simulation<D>::collide(double dt) {
  if (options.collision_distance_over_dp <= 0.0) return;
  auto& P = domain_.particles;
  const double distance = options.collision_distance_over_dp * options.dp;
  const std::size_t n = P.real_count();
  parallel_for(n, [&](std::size_t i) {
    scratch_[i] = P.kind[i] == Kind::fluid
                      ? collision_velocity_change<D>(i, P, list_, distance, options.collision_restitution)
                      : Vec<D>::Zero();
  });
  if (bodies_)
    bodies_->add_collision_forces(domain_, list_, distance, options.collision_restitution, particle_volume(), dt);
  parallel_for(n, [&](std::size_t i) {
    if (P.kind[i] != Kind::fluid) return;
    P.velocity[i] += scratch_[i];
    P.position[i] += dt * scratch_[i];
  });
  domain_.refresh({HaloField::motion});
}

// Rigid bodies: the fluid's force in, one rigid step of the same dt, boundary particles to the new poses.
template <int D>
void Simulation<D>::move_bodies(double dt) {
  if (!bodies_) return;
  bodies_->advance(time_ + dt, dt);
  bodies_->place_particles(domain_.particles, time_ + dt);
  domain_.refresh({HaloField::motion, HaloField::wall_normal});  // the ghosts of body particles
}

// Problem code of real particle i, most severe highest: 4 non-finite, 2 collapse, 1 speed, 0 none. Leaving the
// domain is not one: through an open side it is a splash (remove_particles_that_left), through a wall
// wall_crossing_report tells it.
template <int D>
int Simulation<D>::problem_code(std::size_t i) const {
  const auto& P = domain_.particles;
  const auto& x = P.position[i];
  if (!x.allFinite() || !P.velocity[i].allFinite() || !std::isfinite(P.pressure[i]) ||
      !std::isfinite(P.number_density[i]))
    return 4;
  if (P.kind[i] != Kind::fluid) return 0;
  if (P.number_density[i] > options.max_number_density_ratio * lattice.n0) return 2;
  const double u_max = options.max_speed_over_c0 * options.sound_speed;
  if (P.velocity[i].squaredNorm() > u_max * u_max) return 1;
  return 0;
}

// Real particles only (a ghost equals its source).
template <int D>
std::optional<Instability> Simulation<D>::check() const {
  const int worst =
      static_cast<int>(domain_.max_over_owned(0.0, [&](std::size_t i) { return double(problem_code(i)); }));
  if (worst == 0) return std::nullopt;
  return problem_report(worst);
}

// The particle of lowest id with problem code `worst` (independent of the thread and process count), as an
// instability.
template <int D>
Instability Simulation<D>::problem_report(int worst) const {
  const auto& P = domain_.particles;
  const auto found = domain_.template lowest_id_where<D + 2>(
      [&](std::size_t i) { return problem_code(i) == worst; },
      [&](std::size_t i) {
        std::array<double, D + 2> v;
        for (int k = 0; k < D; ++k) v[k] = P.position[i][k];
        v[D] = P.number_density[i] / lattice.n0;
        v[D + 1] = P.velocity[i].norm();
        return v;
      });
  Instability s;
  s.time = time_;
  s.step = step_count_;
  if (!found) return s;  // not reached: `worst` came from a particle
  const auto& [id, v] = *found;
  s.particle = id;
  s.position.assign(v.begin(), v.begin() + D);
  const double ratio = v[D];
  switch (worst) {
    case 4: s.reason = "non-finite position, velocity, pressure or number density"; break;
    case 2:
      s.reason = "number-density collapse: n/n0 = " + std::to_string(ratio) + " exceeds checks.max_number_density_ratio";
      break;
    default:
      s.reason = "speed " + std::to_string(v[D + 1]) + " m/s exceeds checks.max_speed_over_c0 * c0";
  }
  return s;
}

// Periodic: ghosts count (they are the fluid beyond the period's ends), so a point near an end sees all its water.
template <int D>
double Simulation<D>::fluid_number_density_at(const Vec<D>& point) const {
  if (domain_.distributed()) throw std::logic_error("fluid_number_density_at on several processes (not yet)");
  const auto& P = domain_.particles;
  const double r_e = re();
  double n = 0.0;
  grid_.for_each_near(point, grid_.cell_size(), P.position, [&](std::uint32_t j, double r2) {
    if (P.kind[j] == Kind::fluid) n += kernel_weight(std::sqrt(r2), r_e);
  });
  return n;
}

namespace {

// The solves' counts field by field (StateWriter::io and StateReader::io): a struct's padding is not state.
template <class Stream, class Stats, class Report>
void viscous_solves_io(Stream& s, Stats& stats, Report& last) {
  s.io(stats.solves);
  s.io(stats.iterations);
  s.io(stats.most_iterations);
  s.io(stats.largest_residual);
  s.io(stats.unconverged);
  s.io(last.iterations);
  s.io(last.residual);
  s.io(last.converged);
}

}  // namespace

template <int D>
void Simulation<D>::save_state_after_particles(StateWriter& out) const {
  out.put(domain_.particles.body_frames.body);
  out.put(domain_.particles.body_frames.offset);
  out.put(domain_.particles.body_frames.normal);
  out.put(time_);
  out.put(step_count_);
  out.put(limit_counts_);
  out.put(largest_number_density_ratio_);
  out.put(largest_number_density_ratio_time_);
  out.put(rebuilds_);
  viscous_solves_io(out, viscous_solves_, last_viscous_solve_);
  out.put(options.velocity_damping_rate);
  out.put(rheology_suspended_);
  out.put(bodies_ != nullptr);
  if (bodies_) bodies_->save_state(out);
}

// The state after the particle section (save_state_after_particles), read back.
template <int D>
void Simulation<D>::read_state_after_particles(StateReader& in) {
  in.get(domain_.particles.body_frames.body);
  in.get(domain_.particles.body_frames.offset);
  in.get(domain_.particles.body_frames.normal);
  in.get(time_);
  in.get(step_count_);
  in.get(limit_counts_);
  in.get(largest_number_density_ratio_);
  in.get(largest_number_density_ratio_time_);
  in.get(rebuilds_);
  viscous_solves_io(in, viscous_solves_, last_viscous_solve_);
  in.get(options.velocity_damping_rate);
  in.get(rheology_suspended_);
  if (in.get<bool>() != (bodies_ != nullptr)) throw std::runtime_error("the checkpoint's bodies are not the scene's");
  if (bodies_) bodies_->restore_state(in);
  for (std::size_t i = 0; i < domain_.particles.real_count(); ++i)
    if (domain_.particles.body_frame[i] >= static_cast<std::int32_t>(domain_.particles.body_frames.body.size()))
      throw std::runtime_error("the checkpoint's body particles are not its bodies'");
}

template <int D>
void Simulation<D>::restore_state(StateReader& in) {
  // On several processes (a scene built in parts) each reads a part of the particles, in id order: what one refuses,
  // all refuse, before the particles go to their processes.
  const bool shared = domain_.distributed();
  const auto made = static_cast<std::size_t>(domain_.sum_over_processes(std::int64_t(domain_.particles.id_end())));
  std::string refusal;
  bool correction = false;
  try {
    correction = read_particle_section(in, made);
    read_state_after_particles(in);
  } catch (const std::runtime_error& e) {
    if (!shared) throw;
    refusal = e.what();
  }
  if (shared) {
    std::int64_t refused = refusal.empty() ? 0 : 1;
    domain_.communicator()->max(&refused, 1);
    if (refused != 0 && refusal.empty()) throw StateRefusedElsewhere("another process refused its part of the checkpoint");
    if (refused != 0) throw std::runtime_error(refusal);
    share_restored_particles(correction);
  }
  // Stored, given ghosts, a neighbour list (built from the positions of the last re-sort) and the ghosts' fields as
  // the saved run held them; the semi-implicit predictor's buffer is filled by the next step.
  store_as_one_process(correction);
  scratch_.assign(domain_.particles.size(), Vec<D>::Zero());
  predictor_acceleration_.clear();
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace slide
