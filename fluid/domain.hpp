#pragma once
// The domain seam (DESIGN.md, "One domain seam"): the particles this process owns, their ghost copies, the halo each
// stage declares its neighbours read, and every reduction over particles. A stage computes the owned particles only
// (owned_count()), then refreshes the fields the next stage reads of its neighbours; the time-step limits, the checks
// and the largest speed reduce over the owned particles here.
//
// One process: the ghosts are the periodic images and the mirror images across planes of symmetry (fluid/ghosts.hpp:
// behind the owned particles in every array, rebuilt with the neighbour list, refreshed between). Several processes
// (set_communicator): each owns the particles of its cells of the neighbour grid (fluid/cell_partition.hpp), and the
// ghosts are every particle and image within reach of them, its own images included (fluid/process_halo.hpp):
// refresh() is then an exchange, the reductions combine across processes, and the stages do not change. Maxima are
// exact in any order; sums over particles are exact (fluid/exact_sum.hpp) and neighbour sums run in id order, so
// results are the same to the bit for any number of threads and processes.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "fluid/communicator.hpp"
#include "fluid/domain_options.hpp"
#include "fluid/exact_sum.hpp"
#include "fluid/process_halo.hpp"
#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"
#include "fluid/ghosts.hpp"

namespace slide {

// What a stage's neighbours read beyond the motion: each is one per-particle array carried to the ghosts. `motion` is
// position (the ghost's image of it), velocity and acceleration, which every stage that moves particles changes (and
// the owned particles on a plane of symmetry are first held on it: fluid/ghosts.hpp, hold_on_planes);
// `wall_normal` turns with a body.
enum class HaloField {
  motion,
  velocity,
  number_density,
  pressure,
  gradient_correction,
  viscosity,
  wall_fraction,
  wall_fill,
  wall_normal
};

// What the exchanges between processes cost so far (tools/bench --mpi): seconds in them on this process (waiting for
// the others included), and bytes this process sent to others.
struct CommunicationCost {
  double halo_seconds = 0.0;          // refreshing the ghosts' fields between re-sorts
  double rebuild_seconds = 0.0;       // at re-sorts: migration, repartitioning, new ghosts
  double reduction_seconds = 0.0;     // maxima and sums across processes
  double bytes_sent = 0.0;
};

template <int D>
class Domain {
 public:
  // The owned particles, then their ghosts (Particles::real_count() are owned).
  Particles<D> particles;

  // The period along x, if any (fluid/periodic.hpp), and the planes of symmetry (fluid/mirror_plane.hpp); set before
  // the first rebuild of the ghosts.
  void set_ghost_layout(const GhostLayout& layout) { layout_ = layout; }
  const GhostLayout& ghost_layout() const { return layout_; }

  std::size_t owned_count() const { return particles.real_count(); }

  // The processes of the run, before the first rebuild, which shares the cells out by their particles. `whole`: every
  // process holds every particle (a scene built whole), and each keeps its cells'; otherwise each holds a part of them
  // (a 3-D scene built in parts, cases/build_share.hpp), and each particle goes to its cells' process. Not set, or one
  // process: a run without MPI.
  void set_communicator(std::shared_ptr<const Communicator> comm, bool whole = true) {
    comm_ = std::move(comm);
    replicated_ = distributed() && whole;
    unpartitioned_ = distributed();
  }
  bool distributed() const { return comm_ && comm_->size() > 1; }
  const Communicator* communicator() const { return comm_.get(); }
  // How many cells around its own a process holds ghosts from (fluid/process_halo.hpp): at least one.
  void set_halo_reach(int cells) { halo_reach_ = std::max(1, cells); }
  // Repartition when the largest process's share of the particles exceeds the mean by this factor.
  void set_rebalance_imbalance(double factor) { rebalance_imbalance_ = factor; }
  double rebalance_imbalance() const { return rebalance_imbalance_; }
  // The imbalance above which redistribute() shares the cells anew: a share may grow to this times the mean.
  double imbalance_before_rebalance() const { return std::max(rebalance_imbalance_, 1.1 * imbalance_after_partition_); }
  long repartitions() const { return repartitions_; }
  const CommunicationCost& communication_cost() const { return cost_; }

  // After drop_ghosts and bring_inside, before the re-sort (several processes): the owned particles that moved into
  // another process's cells go to it; the first time, each process keeps its share of all; when the shares differ by
  // more than the rebalance factor, the cells are shared anew by their particles and the particles follow.
  void redistribute(const NeighborGrid<D>& grid) {
    if (!distributed()) return;
    const Stopwatch watch(cost_.rebuild_seconds);
    if (unpartitioned_) {
      std::vector<std::int64_t> weights = local_cell_weights(grid);
      if (!replicated_) comm_->sum(weights.data(), weights.size());
      partition(grid, weights, false);
      if (replicated_) {
        halo_.keep_own(particles, grid, comm_->rank());
      } else {
        halo_.migrate(particles, grid, *comm_);
        particles.for_each_array([](auto& v) { v.shrink_to_fit(); });  // (grown by what came in)
      }
      replicated_ = unpartitioned_ = false;
      imbalance_after_partition_ = imbalance();
      return;
    }
    halo_.migrate(particles, grid, *comm_);
    // Shared anew when the shares differ by more than the factor, and by a tenth more than right after the last
    // partition: a partition of whole cells may not reach the factor, and would otherwise be redone at every re-sort.
    if (imbalance() > imbalance_before_rebalance()) {
      std::vector<std::int64_t> weights = local_cell_weights(grid);
      comm_->sum(weights.data(), weights.size());
      partition(grid, weights, true);
      halo_.migrate(particles, grid, *comm_);
      imbalance_after_partition_ = imbalance();
    }
  }
  // Each process's owned particles, by process (every process calls it).
  std::vector<std::int64_t> owned_counts() const {
    const int processes = comm_ ? comm_->size() : 1, rank = comm_ ? comm_->rank() : 0;
    std::vector<std::int64_t> counts(static_cast<std::size_t>(processes), 0);
    counts[static_cast<std::size_t>(rank)] = static_cast<std::int64_t>(owned_count());
    if (comm_) comm_->sum(counts.data(), counts.size());
    return counts;
  }
  // The largest process's owned particles over the mean (1 for one process).
  double imbalance() const {
    if (!distributed()) return 1.0;
    const std::vector<std::int64_t> counts = owned_counts();
    std::int64_t total = 0, most = 0;
    for (const std::int64_t c : counts) {
      total += c;
      most = std::max(most, c);
    }
    return total == 0 ? 1.0 : double(most) * double(counts.size()) / double(total);
  }

  // The axes (bit a: axis a) of the planes of symmetry that owned particle i lies on (fluid/mirror_plane.hpp, holds,
  // within the last make_ghosts' depth): it is its own image across them, and its velocity across them is zero.
  std::uint8_t planes_holding(std::size_t i) const {
    std::uint8_t axes = 0;
    for (const MirrorPlane& m : layout_.mirrors)
      if (m.holds(particles.position[i][m.axis], ghost_depth_)) axes = static_cast<std::uint8_t>(axes | (1u << m.axis));
    return axes;
  }

  // Before the owned particles are re-sorted or removed: the ghosts go (every array back to the owned particles).
  void drop_ghosts() {
    if (layout_.any() || distributed()) remove_ghosts(particles);
  }
  // Owned particles that crossed an end of the period come back into it, those that crossed a plane of symmetry come
  // back as their image (no ghosts present).
  void bring_inside() {
    if (layout_.period) wrap_positions(particles, *layout_.period);
    reflect_into_mirrors(particles, layout_.mirrors);
  }
  // After a re-sort: ghosts afresh for the owned particles within `depth` (the neighbour list's radius) of the
  // period's ends and the planes of symmetry. Returns whether there are any.
  // One process: the grid is not needed.
  bool make_ghosts(double depth) {
    if (distributed()) throw std::logic_error("Domain::make_ghosts: several processes need the grid");
    return make_ghosts(depth, NeighborGrid<D>());
  }
  bool make_ghosts(double depth, const NeighborGrid<D>& grid) {
    ghost_depth_ = depth;
    if (distributed()) {
      const Stopwatch watch(cost_.rebuild_seconds);
      halo_.make_ghosts(particles, grid, layout_, depth, *comm_);
      cost_.bytes_sent = double(halo_.bytes_sent());
      return true;
    }
    if (layout_.any()) add_ghosts(particles, layout_, depth);
    return particles.ghost_count() != 0;
  }

  // The owned particles' `fields` carried to their ghosts: what the next stage reads of its neighbours.
  void refresh(std::initializer_list<HaloField> fields) {
    if (particles.ghost_count() == 0 && !distributed()) return;
    for (const HaloField f : fields) refresh(f);
  }

  // The largest f(i) over the owned particles, from `init` (exact: max does not depend on the order).
  template <class F>
  double max_over_owned(double init, F&& f) const {
    double m = parallel_max(owned_count(), init, f);
    if (distributed()) {
      const Stopwatch watch(cost_.reduction_seconds);
      comm_->max(&m, 1);
    }
    return m;
  }
  // Several maxima in one pass (component k of f(i) into component k).
  template <std::size_t K, class F>
  std::array<double, K> max_each_over_owned(const std::array<double, K>& init, F&& f) const {
    std::array<double, K> m = parallel_max_each<K>(owned_count(), init, f);
    if (distributed()) {
      const Stopwatch watch(cost_.reduction_seconds);
      comm_->max(m.data(), K);
    }
    return m;
  }
  // The owned particle of lowest id over all processes for which pick(i) holds, with values(i) (K numbers), the same
  // on every process; nothing where none holds anywhere.
  template <std::size_t K, class Pick, class Values>
  std::optional<std::pair<ParticleId, std::array<double, K>>> lowest_id_where(Pick&& pick, Values&& values) const {
    const auto& P = particles;
    std::size_t best = owned_count();
    for (std::size_t i = 0; i < owned_count(); ++i)
      if (pick(i) && (best == owned_count() || P.id[i] < P.id[best])) best = i;
    std::int64_t negated = best < owned_count() ? -static_cast<std::int64_t>(P.id[best]) : INT64_MIN;
    if (distributed()) comm_->max(&negated, 1);
    if (negated == INT64_MIN) return std::nullopt;
    const auto id = static_cast<ParticleId>(-negated);
    // Its owner's values as bit patterns, every other process's zero, summed: exact, NaN and infinities included.
    std::array<double, K> v{};
    if (best < owned_count() && P.id[best] == id) v = values(best);
    if (distributed()) {
      std::array<std::int64_t, K> bits;
      std::memcpy(bits.data(), v.data(), sizeof(v));
      comm_->sum(bits.data(), K);
      std::memcpy(v.data(), bits.data(), sizeof(v));
    }
    return std::pair{id, v};
  }
  // Sums by group over the owned particles (a rigid body's force and torque over its boundary particles): entry g
  // of the result is the sum of values(i) over every owned i with group_of(i) == g (component by component; i with
  // group_of(i) < 0 count nowhere). Each sum is exact and rounded once (fluid/exact_sum.hpp), so it does not depend on
  // the order of the terms: the same bits for any storage order, thread count and, combined across processes, split.
  template <std::size_t K, class GroupOf, class Values>
  std::vector<std::array<double, K>> sum_by_group(std::size_t groups, GroupOf&& group_of, Values&& values) const {
    std::vector<std::array<ExactSum, K>> sums(groups);
    for (std::size_t i = 0; i < owned_count(); ++i) {
      const int g = group_of(i);
      if (g < 0) continue;
      const std::array<double, K> v = values(i);
      for (std::size_t k = 0; k < K; ++k) sums[static_cast<std::size_t>(g)][k].add(v[k]);
    }
    std::vector<std::array<double, K>> out(groups);
    combine(sums.empty() ? nullptr : sums.front().data(), groups * K);
    for (std::size_t g = 0; g < groups; ++g)
      for (std::size_t k = 0; k < K; ++k) out[g][k] = sums[g][k].value();
    return out;
  }

  // Several processes: each of the `count` exact sums becomes the sum of every process's (the digits summed: exact,
  // whatever the split). One process: unchanged.
  void combine(ExactSum* sums, std::size_t count) const {
    if (!distributed()) return;
    const Stopwatch watch(cost_.reduction_seconds);
    sum_across(*comm_, sums, count);
  }


  // A stage's own per-particle array (not one of the particles'), its owned entries carried to the ghosts as a
  // field's are (vectors turned as the image turns them).
  template <class T>
  void refresh_values(std::vector<T>& v) {
    if (!distributed()) {
      copy_to_ghosts(particles, v);
      return;
    }
    const Stopwatch watch(cost_.halo_seconds);
    halo_.refresh(particles, v, *comm_);
  }
  // The sum of `mine` over the processes (one process: mine).
  std::int64_t sum_over_processes(std::int64_t mine) const {
    if (distributed()) comm_->sum(&mine, 1);
    return mine;
  }

  // Whether this process owns the cell of the grid that `point` lies in (one process: every cell). A quantity summed
  // over points of space rather than particles (a body face's samples) is summed by the owner of each point's cell,
  // whose ghosts hold every particle within a cell of it.
  bool owns_point(const Vec<D>& point, const NeighborGrid<D>& grid) const {
    return !distributed() || halo_.owner(grid.linear(grid.cell_of(point))) == comm_->rank();
  }
  // The process that owns the cell `point` lies in (several processes, after the cells are shared out).
  int owner_of_point(const Vec<D>& point, const NeighborGrid<D>& grid) const { return halo_.owner_of(point, grid); }

  // A resumed run whose processes each read a part of the checkpoint's particles (coupling/simulation.hpp,
  // restore_state): the cells shared out anew by where `at` puts every process's particles (their positions at the
  // last re-sort), as the first re-sort of a scene built in parts shares them; `send` then gives each particle to its
  // cells' process (no ghosts present). Several processes.
  template <class Send>
  void share_cells_by(const NeighborGrid<D>& grid, const std::vector<Vec<D>>& at, Send&& send) {
    std::vector<std::int64_t> weights(grid.total_cells(), 0);
    for (std::size_t i = 0; i < owned_count(); ++i) ++weights[grid.linear(grid.cell_of(at[i]))];
    comm_->sum(weights.data(), weights.size());
    partition(grid, weights, false);
    replicated_ = unpartitioned_ = false;
    send();
    imbalance_after_partition_ = imbalance();
  }

 private:
  void refresh(HaloField f) {
    auto& P = particles;
    if (distributed()) {
      refresh_across_processes(f);
      return;
    }
    switch (f) {
      case HaloField::motion:
        hold_on_planes(P, layout_.mirrors, ghost_depth_);  // before its images are placed from it
        sync_ghost_motion(P);
        return;
      case HaloField::velocity: copy_to_ghosts(P, P.velocity); return;
      case HaloField::number_density: copy_to_ghosts(P, P.number_density); return;
      case HaloField::pressure: copy_to_ghosts(P, P.pressure); return;
      case HaloField::gradient_correction: copy_to_ghosts(P, P.gradient_correction); return;
      case HaloField::viscosity: copy_to_ghosts(P, P.viscosity); return;
      case HaloField::wall_fraction: copy_to_ghosts(P, P.wall_fraction); return;
      case HaloField::wall_fill: copy_to_ghosts(P, P.wall_fill); return;
      case HaloField::wall_normal: copy_to_ghosts(P, P.wall_normal); return;
    }
  }

  void refresh_across_processes(HaloField f) {
    const Stopwatch watch(cost_.halo_seconds);
    refresh_fields_across_processes(f);
    cost_.bytes_sent = double(halo_.bytes_sent());
  }
  void refresh_fields_across_processes(HaloField f) {
    auto& P = particles;
    const Communicator& c = *comm_;
    switch (f) {
      case HaloField::motion:
        hold_on_planes(P, layout_.mirrors, ghost_depth_);
        halo_.refresh_motion(P, c);
        return;
      case HaloField::velocity: halo_.refresh(P, P.velocity, c); return;
      case HaloField::number_density: halo_.refresh(P, P.number_density, c); return;
      case HaloField::pressure: halo_.refresh(P, P.pressure, c); return;
      case HaloField::gradient_correction: halo_.refresh(P, P.gradient_correction, c); return;
      case HaloField::viscosity: halo_.refresh(P, P.viscosity, c); return;
      case HaloField::wall_fraction: halo_.refresh(P, P.wall_fraction, c); return;
      case HaloField::wall_fill: halo_.refresh(P, P.wall_fill, c); return;
      case HaloField::wall_normal: halo_.refresh(P, P.wall_normal, c); return;
    }
  }
  // This process's owned particles per cell of the grid.
  std::vector<std::int64_t> local_cell_weights(const NeighborGrid<D>& grid) const {
    std::vector<std::int64_t> w(grid.total_cells(), 0);
    for (std::size_t i = 0; i < owned_count(); ++i) ++w[grid.linear(grid.cell_of(particles.position[i]))];
    return w;
  }
  void partition(const NeighborGrid<D>& grid, const std::vector<std::int64_t>& weights, bool again) {
    halo_.set_partition(CellPartition<D>(grid.cells(), weights, comm_->size()), grid, halo_reach_);
    if (again) ++repartitions_;
  }

  // Adds the seconds of its scope to a total (const members time their reductions: the total is mutable).
  class Stopwatch {
   public:
    explicit Stopwatch(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
    ~Stopwatch() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

   private:
    double& total_;
    std::chrono::steady_clock::time_point start_;
  };

  GhostLayout layout_;
  double ghost_depth_ = 0.0;  // the depth of the last make_ghosts
  mutable CommunicationCost cost_;
  std::shared_ptr<const Communicator> comm_;
  ProcessHalo<D> halo_;
  bool replicated_ = false;  // every process holds every particle (before the first rebuild)
  bool unpartitioned_ = false;  // the cells not yet shared out (before the first rebuild)
  int halo_reach_ = 1;
  double rebalance_imbalance_ = DomainOptions{}.rebalance_imbalance;
  double imbalance_after_partition_ = 1.0;
  long repartitions_ = 0;
};

}  // namespace slide
