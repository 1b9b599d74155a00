#pragma once
// The particle store: one array per quantity (structure of arrays), all of the same length.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <stdexcept>
#include <vector>

#include "fluid/name_table.hpp"
#include "fluid/parallel.hpp"
#include "fluid/vec.hpp"

namespace slide {

// A particle's global identity (DESIGN.md, "One domain seam"): 64 bits, kept through re-sorting, removal and, with
// many processes, migration; every output is ordered by it.
using ParticleId = std::uint64_t;

enum class Kind : std::uint8_t {
  fluid = 0,  // moves with the flow (water or sediment, told apart by phase)
  wall = 1,   // first boundary layer: carries pressure, is seen by the pressure gradient and viscosity
  dummy = 2,  // further boundary layers that complete the kernel support behind the wall
};

// The names of the kinds, as snapshots state them next to their codes.
inline constexpr auto kind_names =
    make_name_table<Kind>(std::pair{Kind::fluid, "fluid"}, std::pair{Kind::wall, "wall"}, std::pair{Kind::dummy, "dummy"});

template <int D>
struct Particles {
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<Vec<D>> acceleration;  // fluid: total of the last step (force time-step limit); body particles: their
                                     // body's rigid acceleration; fixed walls: zero
  std::vector<double> pressure;
  std::vector<double> number_density;
  std::vector<double> density;    // reference density of the particle's phase, kg/m^3
  std::vector<double> viscosity;  // dynamic viscosity, Pa s
  // Fluid particles: the fraction s = mu_w / mu of their viscosity that their wall pairs use, below 1 where a Coulomb
  // basal friction bounds the wall's shear stress (fluid/basal_friction.hpp); 1, the no-slip wall, otherwise.
  std::vector<double> wall_fraction;
  std::vector<std::uint8_t> phase;
  std::vector<Kind> kind;
  std::vector<ParticleId> id;  // stable identity: the index at creation, kept through re-sorting
  // Boundary particles: unit normal of their wall face, pointing into the fluid, and their distance behind the
  // face (positive). Fluid particles hold zeros.
  std::vector<Vec<D>> wall_normal;
  std::vector<double> wall_depth;
  // Boundary particles: the weight with which they count in their neighbours' number density (1 unless the wall
  // model mirrors the fluid, fluid/wall_pressure.hpp). Fluid particles hold 1.
  std::vector<double> wall_fill;
  // Each particle's corrective matrix for the corrected pressure gradient, set where the pressure is
  // (fluid/corrective_matrix.hpp); per step, not carried through re-sorting.
  std::vector<Mat<D>> gradient_correction;
  // Boundary particles of a rigid body: their entry in body_frames (-1 for fixed walls and fluid). Their world
  // position, velocity and normal are set from the body's pose every step, never integrated.
  std::vector<std::int32_t> body_frame;
  // One entry per body particle, not per particle (32 bytes a particle that only body particles used): the body's
  // index, and the particle's offset from the body's centre of mass and its normal, both in the body's frame (angle 0).
  struct BodyFrames {
    std::vector<std::int32_t> body;
    std::vector<Vec<D>> offset, normal;
  } body_frames;

  // The body particle i belongs to, or -1.
  int body_of(std::size_t i) const { return body_frame[i] < 0 ? -1 : body_frames.body[body_frame[i]]; }
  void attach_to_body(std::size_t i, int b, const Vec<D>& offset, const Vec<D>& normal) {
    body_frame[i] = add_body_frame(b, offset, normal);
  }
  // A frame alone, for a body particle that another process holds: every process keeps every body particle's frame,
  // in the order they were made, so that an entry's index (body_frame, which travels with the particle) is the same
  // on all of them.
  std::int32_t add_body_frame(int b, const Vec<D>& offset, const Vec<D>& normal) {
    body_frames.body.push_back(b);
    body_frames.offset.push_back(offset);
    body_frames.normal.push_back(normal);
    return static_cast<std::int32_t>(body_frames.body.size() - 1);
  }

  // Ghosts (fluid/ghosts.hpp: periodic and mirror images; fluid/process_halo.hpp: other processes' particles). The
  // arrays above hold the real (owned) particles first, then ghost_flip.size() ghosts: ghost g, at index
  // real_count() + g, is an image of a real particle (ghost_source[g] here, or remote_source: owned by another process),
  // equal to it in every array except that its position is the source's with the components along the axes in the
  // bits of ghost_flip[g] negated, plus ghost_offset[g], and its vectors are negated along those axes too; its id is
  // its source's (the order key tells them apart). Removing the ghosts truncates the arrays. Without periodic ends,
  // planes of symmetry or other processes there are none and real_count() == size().
  static constexpr std::uint32_t remote_source = 0xffffffffu;
  std::vector<std::uint32_t> ghost_source;
  std::vector<std::uint8_t> ghost_flip;
  std::vector<Vec<D>> ghost_offset;
  // Particles taken out of a run (remove_keeping_ids: they left the domain) since the ids were last made dense. The
  // real ids lie in 0 .. real_count() + removed_count - 1 (one process: the run's own).
  std::size_t removed_count = 0;
  std::size_t id_end() const { return real_count() + removed_count; }

  std::size_t size() const { return position.size(); }
  std::size_t ghost_count() const { return ghost_flip.size(); }
  std::size_t real_count() const { return size() - ghost_flip.size(); }
  // The real particle that index j stands for: j itself, or a ghost's source (on this process: not for a ghost of
  // another process's particle).
  std::size_t real_index(std::size_t j) const {
    const std::size_t r = real_count();
    if (j < r) return j;
    const std::uint32_t s = ghost_source[j - r];
    if (s == remote_source) throw std::logic_error("real_index of another process's particle");
    return s;
  }

  // Where particle j comes among the particles of its cell (fluid/neighbor_grid.hpp, bin with a key), and so in every
  // neighbour sum: a particle by its id, an image after its source, by which image it is (its flip, and its periodic
  // shift's sign where x is not flipped). Another process's particle, a ghost that is no image (no flip, no shift),
  // comes where it would as a real particle: the order is the same for any split. Distinct for distinct particles
  // while ids stay below 2^59.
  std::uint64_t order_key(std::size_t j) const {
    const std::size_t r = real_count();
    if (j < r) return id[j] << 5;
    const std::size_t g = j - r;
    const unsigned flip = ghost_flip[g];
    const double shift = (flip & 1u) ? 0.0 : ghost_offset[g][0];
    const unsigned periodic = shift > 0.0 ? 1u : shift < 0.0 ? 2u : 0u;
    if (flip == 0 && periodic == 0) return id[j] << 5;
    return id[j] << 5 | (1u + flip + 8u * periodic);
  }

  // Calls f(array) for every per-particle array (each of length size()): the one list of them, so that re-sorting,
  // ghost creation, copying and truncation cannot miss one.
  template <class F>
  void for_each_array(F&& f) {
    f(position);
    f(velocity);
    f(acceleration);
    f(pressure);
    f(number_density);
    f(density);
    f(viscosity);
    f(wall_fraction);
    f(phase);
    f(kind);
    f(id);
    f(wall_normal);
    f(wall_depth);
    f(wall_fill);
    f(body_frame);
  }
  template <class F>
  void for_each_array(F&& f) const {
    const_cast<Particles*>(this)->for_each_array([&](auto& v) { f(static_cast<const std::decay_t<decltype(v)>&>(v)); });
  }

  std::size_t add(const Vec<D>& x, Kind k, std::uint8_t phase_index, double rho, double mu) {
    if (!ghost_flip.empty()) throw std::logic_error("Particles::add with ghosts present");
    const std::size_t i = size();
    position.push_back(x);
    velocity.push_back(Vec<D>::Zero());
    acceleration.push_back(Vec<D>::Zero());
    pressure.push_back(0.0);
    number_density.push_back(0.0);
    density.push_back(rho);
    viscosity.push_back(mu);
    wall_fraction.push_back(1.0);
    phase.push_back(phase_index);
    kind.push_back(k);
    id.push_back(static_cast<ParticleId>(i));
    wall_normal.push_back(Vec<D>::Zero());
    wall_depth.push_back(0.0);
    wall_fill.push_back(1.0);
    body_frame.push_back(-1);
    return i;
  }

  // Reorders every array so that new index i holds what was at old index order[i] (real particles only: ghosts
  // are removed first, fluid/periodic.hpp). Each array is copied into `buffer` and gathered back, so that a re-sort
  // allocates nothing: a new array per quantity at every re-sort had left the heap fragmented, 40 bytes a particle
  // of resident size in the bench case's first 0.05 s (measured against a fixed mmap threshold).
  void reorder(const std::vector<std::uint32_t>& order, std::vector<Vec<D>>& buffer) {
    if (!ghost_flip.empty()) throw std::logic_error("Particles::reorder with ghosts present");
    if (buffer.size() < size()) buffer.resize(size());
    for_each_array([&](auto& v) { permute_through(v, order, buffer); });
  }

  // Removes every particle for which drop(i) holds (real particles only: no ghosts may be present), keeping the
  // others in their order and their ids (a particle's id names it in every snapshot of a run).
  template <class Drop>
  void remove_keeping_ids(Drop drop) {
    if (!ghost_flip.empty()) throw std::logic_error("Particles::remove_keeping_ids with ghosts present");
    std::vector<std::uint32_t> keep;
    for (std::size_t i = 0; i < size(); ++i)
      if (!drop(i)) keep.push_back(static_cast<std::uint32_t>(i));
    removed_count += size() - keep.size();
    for_each_array([&](auto& v) {
      permute(v, keep);
      v.resize(keep.size());
    });
  }

  // Removes every particle for which drop(i) holds (real particles only: no ghosts may be present), keeping the
  // others in their order, and renumbers the ids 0 .. size() - 1 in their former order, so ids stay creation ranks.
  template <class Drop>
  void remove_if(Drop drop) {
    if (!ghost_flip.empty()) throw std::logic_error("Particles::remove_if with ghosts present");
    std::vector<std::uint32_t> keep;
    for (std::size_t i = 0; i < size(); ++i)
      if (!drop(i)) keep.push_back(static_cast<std::uint32_t>(i));
    for_each_array([&](auto& v) {
      permute(v, keep);
      v.resize(keep.size());
    });
    std::vector<std::uint32_t> by_id(size());
    for (std::uint32_t i = 0; i < by_id.size(); ++i) by_id[i] = i;
    std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t a, std::uint32_t b) { return id[a] < id[b]; });
    for (std::uint32_t rank = 0; rank < by_id.size(); ++rank) id[by_id[rank]] = rank;
    removed_count = 0;
  }

  // v[i] = old v[order[i]], the old values copied into `buffer` (at least as many bytes as v holds; every array's
  // element is a plain value no larger than Vec<D>: a number, a code, or a fixed-size Eigen vector of doubles, which
  // holds just its coefficients).
  template <class T>
  static void permute_through(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::vector<Vec<D>>& buffer) {
    static_assert((std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec<D>>) && sizeof(T) <= sizeof(Vec<D>));
    unsigned char* old = reinterpret_cast<unsigned char*>(buffer.data());
    std::memcpy(old, v.data(), v.size() * sizeof(T));
    // Through void*: the element may be an Eigen vector, which GCC's -Wclass-memaccess flags though it holds just
    // its coefficients (static_assert above).
    // The gather in parallel: each index is written by one thread, from the copy, so the result is the serial one.
    parallel_for(order.size(), [&](std::size_t i) {
      std::memcpy(static_cast<void*>(&v[i]), old + std::size_t(order[i]) * sizeof(T), sizeof(T));
    });
  }

  template <class T>
  static void permute(std::vector<T>& v, const std::vector<std::uint32_t>& order) {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
    v.swap(out);
  }
};

}  // namespace slide
