#pragma once
// Other processes' particles as ghosts (DESIGN.md, "One domain seam"; the multi-process draft of SPHinXsys treats them
// as periodic ghosts, and so does this): each process owns the particles of the neighbour grid's cells its partition
// gives it (fluid/cell_partition.hpp), and holds as ghosts every particle, and every periodic or mirror image of one,
// that lies within `reach` cells of one of its own cells. The send lists are made when the neighbour list is rebuilt;
// between rebuilds each stage's fields go along them (refresh).
//
// Why `reach` cells and not one: a particle's neighbours lie in its cell and the cells around it, but a boundary
// particle's mirror image (fluid/wall_pressure.hpp, mirror_fill) lies up to twice its depth behind the wall in front of
// it, and the fluid around that image must be here too (Domain::set_halo_reach).
//
// A ghost is stored as fluid/ghosts.hpp describes (flip, offset, the source's id), with ghost_source remote_source: its
// source may be on this process (a periodic or mirror image of an owned particle) or another. A refresh copies an own
// image's values from its source directly (Own) and another process's through the exchange; either way the value
// becomes the ghost's by the image's flip.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "fluid/cell_partition.hpp"
#include "fluid/communicator.hpp"
#include "fluid/ghosts.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"

namespace slide {

namespace halo_bytes {
template <class T>
void put(std::vector<unsigned char>& out, const T& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}
template <class T>
T get(const unsigned char*& in) {
  T v;
  std::memcpy(static_cast<void*>(&v), in, sizeof(T));
  in += sizeof(T);
  return v;
}
}  // namespace halo_bytes

template <int D>
class ProcessHalo {
 public:
  // A new partition: which process owns each cell, and, for every cell, the processes that own a cell within `reach`
  // cells of it (they need its particles as ghosts).
  void set_partition(CellPartition<D> partition, const NeighborGrid<D>& grid, int reach) {
    partition_ = std::move(partition);
    const auto& cells = grid.cells();
    needers_first_.assign(grid.total_cells() + 1, 0);
    needers_.clear();
    std::vector<int> near;
    std::array<int, D> c{};
    for (std::size_t l = 0; l < grid.total_cells(); ++l) {
      std::size_t rest = l;
      for (int k = 0; k < D; ++k) {
        c[k] = static_cast<int>(rest % static_cast<std::size_t>(cells[k]));
        rest /= static_cast<std::size_t>(cells[k]);
      }
      near.clear();
      for_each_cell_near(c, cells, reach, [&](const std::array<int, D>& q) { near.push_back(owner(grid.linear(q))); });
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      needers_.insert(needers_.end(), near.begin(), near.end());
      needers_first_[l + 1] = static_cast<std::uint32_t>(needers_.size());
    }
  }
  bool has_partition() const { return !partition_.empty(); }
  int owner(std::size_t cell) const { return partition_.owner(cell); }
  int owner_of(const Vec<D>& x, const NeighborGrid<D>& grid) const { return owner(grid.linear(grid.cell_of(x))); }

  // Every process holds every particle (the scene as built): each keeps those of its own cells. No ghosts present.
  void keep_own(Particles<D>& P, const NeighborGrid<D>& grid, int self) const {
    P.remove_keeping_ids([&](std::size_t i) { return owner_of(P.position[i], grid) != self; });
    P.removed_count = 0;  // the others hold them
    P.for_each_array([](auto& v) { v.shrink_to_fit(); });  // the whole scene's storage goes back
  }

  // The owned particles in another process's cells go to it; those it sends are appended. No ghosts present.
  void migrate(Particles<D>& P, const NeighborGrid<D>& grid, const Communicator& comm) const {
    const int self = comm.rank(), processes = comm.size();
    std::vector<std::vector<unsigned char>> out(static_cast<std::size_t>(processes));
    std::vector<char> leaving(P.size(), 0);
    for (std::size_t i = 0; i < P.size(); ++i) {
      const int r = owner_of(P.position[i], grid);
      if (r == self) continue;
      leaving[i] = 1;
      append_record(P, i, out[static_cast<std::size_t>(r)]);
    }
    std::vector<std::size_t> received_bytes;
    const std::vector<unsigned char> in = exchange(out, comm, received_bytes);
    const std::size_t removed = P.removed_count;
    P.remove_keeping_ids([&](std::size_t i) { return leaving[i] != 0; });
    P.removed_count = removed;
    const std::size_t record = record_bytes(P);
    const unsigned char* q = in.data();
    for (std::size_t k = 0; k < in.size() / record; ++k) read_record(P, q);
  }

  // Ghosts afresh (none present): every owned particle and each of its periodic and mirror images (fluid/ghosts.hpp,
  // images_of within `margin`) goes to every process that needs the cell it lies in, this one included for an image
  // and excluded for the particle itself. Ghosts come after the owned particles, by sending process.
  void make_ghosts(Particles<D>& P, const NeighborGrid<D>& grid, const GhostLayout& layout, double margin,
                   const Communicator& comm) {
    if (P.ghost_count() != 0) throw std::logic_error("ProcessHalo::make_ghosts: ghosts are already present");
    const int self = comm.rank();
    const std::size_t processes = static_cast<std::size_t>(comm.size());
    send_.assign(processes, {});
    std::vector<std::vector<unsigned char>> out(processes);
    const std::size_t n = P.real_count();
    const auto send_image = [&](std::size_t i, std::uint8_t flip, const Vec<D>& offset, bool to_self) {
      const std::size_t cell = grid.linear(grid.cell_of(image_point<D>(P.position[i], flip, offset)));
      for (std::uint32_t k = needers_first_[cell]; k < needers_first_[cell + 1]; ++k) {
        const int r = needers_[k];
        if (r == self && !to_self) continue;
        auto& bytes = out[static_cast<std::size_t>(r)];
        send_[static_cast<std::size_t>(r)].push_back(static_cast<std::uint32_t>(i));
        halo_bytes::put(bytes, flip);
        halo_bytes::put(bytes, offset);
        append_record(P, i, bytes);
      }
    };
    for (std::size_t i = 0; i < n; ++i) {
      send_image(i, 0, Vec<D>::Zero(), false);
      if (layout.any())
        images_of<D>(P.position[i], layout, margin,
                     [&](std::uint8_t flip, const Vec<D>& offset) { send_image(i, flip, offset, true); });
    }
    std::vector<std::size_t> received_bytes;
    const std::vector<unsigned char> in = exchange(out, comm, received_bytes);
    const std::size_t entry = ghost_entry_bytes(P);
    received_.resize(processes);
    const unsigned char* q = in.data();
    for (std::size_t r = 0; r < processes; ++r) {
      received_[r] = received_bytes[r] / entry;
      for (std::size_t k = 0; k < received_[r]; ++k) {
        const auto flip = halo_bytes::get<std::uint8_t>(q);
        const auto offset = halo_bytes::get<Vec<D>>(q);
        const std::size_t t = read_record(P, q);
        P.ghost_source.push_back(Particles<D>::remote_source);
        P.ghost_flip.push_back(flip);
        P.ghost_offset.push_back(offset);
        place_image(P, t, P.ghost_count() - 1);
      }
    }
  }

  // One array's values of the owned particles carried to the ghosts made from them: numbers as they are, vectors and
  // corrective matrices as their images (fluid/ghosts.hpp, copy_to_ghosts). Not for positions (refresh_motion).
  template <class T>
  void refresh(Particles<D>& P, std::vector<T>& v, const Communicator& comm) const {
    const std::vector<unsigned char> in = exchange_values(comm, sizeof(T), [&](std::uint32_t i, unsigned char* out) {
      std::memcpy(out, static_cast<const void*>(&v[i]), sizeof(T));
    });
    const std::size_t r0 = P.real_count();
    const Own own = own_images(comm);
    parallel_for(P.ghost_count(), [&](std::size_t g) {
      T value;
      if (const std::uint32_t* source = own.source(g)) {
        value = v[*source];
      } else {
        const unsigned char* q = in.data() + own.received_index(g) * sizeof(T);
        value = halo_bytes::get<T>(q);
      }
      const std::uint8_t flip = P.ghost_flip[g];
      if constexpr (std::is_same_v<T, Vec<D>>) v[r0 + g] = image_vector<D>(value, flip);
      else if constexpr (std::is_same_v<T, Mat<D>>) v[r0 + g] = image_matrix<D>(value, flip);
      else v[r0 + g] = value;
    });
  }

  // Position (as the ghost's image), velocity and acceleration: what every stage that moves particles changes.
  void refresh_motion(Particles<D>& P, const Communicator& comm) const {
    constexpr std::size_t vec = sizeof(Vec<D>);
    const std::vector<unsigned char> in = exchange_values(comm, 3 * vec, [&](std::uint32_t i, unsigned char* out) {
      std::memcpy(out, static_cast<const void*>(&P.position[i]), vec);
      std::memcpy(out + vec, static_cast<const void*>(&P.velocity[i]), vec);
      std::memcpy(out + 2 * vec, static_cast<const void*>(&P.acceleration[i]), vec);
    });
    const std::size_t r0 = P.real_count();
    const Own own = own_images(comm);
    parallel_for(P.ghost_count(), [&](std::size_t g) {
      const std::size_t t = r0 + g;
      const std::uint8_t flip = P.ghost_flip[g];
      if (const std::uint32_t* source = own.source(g)) {
        P.position[t] = image_point<D>(P.position[*source], flip, P.ghost_offset[g]);
        P.velocity[t] = image_vector<D>(P.velocity[*source], flip);
        P.acceleration[t] = image_vector<D>(P.acceleration[*source], flip);
        return;
      }
      const unsigned char* q = in.data() + own.received_index(g) * 3 * vec;
      P.position[t] = image_point<D>(halo_bytes::get<Vec<D>>(q), flip, P.ghost_offset[g]);
      P.velocity[t] = image_vector<D>(halo_bytes::get<Vec<D>>(q), flip);
      P.acceleration[t] = image_vector<D>(halo_bytes::get<Vec<D>>(q), flip);
    });
  }

  // One particle's every array as bytes (a migrating particle, a new ghost, the first process's whole copy of a run:
  // tools/observer_copy.hpp).
  static std::size_t record_bytes(const Particles<D>& P) {
    std::size_t n = 0;
    P.for_each_array([&](const auto& v) { n += sizeof(typename std::decay_t<decltype(v)>::value_type); });
    return n;
  }
  // A ghost's entry in make_ghosts' exchange: its image's flip and offset, and its record.
  static std::size_t ghost_entry_bytes(const Particles<D>& P) { return 1 + sizeof(Vec<D>) + record_bytes(P); }
  static void append_record(const Particles<D>& P, std::size_t i, std::vector<unsigned char>& out) {
    P.for_each_array([&](const auto& v) { halo_bytes::put(out, v[i]); });
  }
  // Appends one particle from its record; returns its index.
  static std::size_t read_record(Particles<D>& P, const unsigned char*& in) {
    const std::size_t t = P.size();
    P.for_each_array([&](auto& v) { v.push_back(halo_bytes::get<typename std::decay_t<decltype(v)>::value_type>(in)); });
    return t;
  }

  // Calls f(q) for every cell q within `reach` cells of c (Chebyshev distance), c included, inside the grid: the
  // cells whose particles a process owning c holds as ghosts (tools/bench --partition counts them the same way).
  template <class F>
  static void for_each_cell_near(const std::array<int, D>& c, const std::array<int, D>& cells, int reach, F&& f) {
    std::array<int, D> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = std::max(c[k] - reach, 0);
      hi[k] = std::min(c[k] + reach, cells[k] - 1);
    }
    std::array<int, D> q = lo;
    while (true) {
      f(q);
      int k = 0;
      for (; k < D; ++k) {
        if (++q[k] <= hi[k]) break;
        q[k] = lo[k];
      }
      if (k == D) return;
    }
  }
  // Bytes sent to other processes so far (tools/bench --mpi).
  std::size_t bytes_sent() const { return bytes_sent_; }

 private:
  // Ghost g (at index t) as its image of the source's values it was received with.
  static void place_image(Particles<D>& P, std::size_t t, std::size_t g) {
    const std::uint8_t flip = P.ghost_flip[g];
    P.position[t] = image_point<D>(P.position[t], flip, P.ghost_offset[g]);
    if (flip == 0) return;
    P.velocity[t] = image_vector<D>(P.velocity[t], flip);
    P.acceleration[t] = image_vector<D>(P.acceleration[t], flip);
    P.wall_normal[t] = image_vector<D>(P.wall_normal[t], flip);
  }
  // The ghosts this process made of its own particles (periodic and mirror images), which a refresh copies from
  // their sources directly (as copy_to_ghosts does on one process) instead of through the exchange: those from this
  // process, [first, first + count) among the ghosts, whose sources are send_[rank] in order.
  struct Own {
    std::size_t first = 0, count = 0;
    const std::uint32_t* sources = nullptr;
    const std::uint32_t* source(std::size_t g) const {
      return g >= first && g < first + count ? sources + (g - first) : nullptr;
    }
    // Another process's ghost g: its entry in what the exchange received (the others' entries, in ghost order).
    std::size_t received_index(std::size_t g) const { return g < first ? g : g - count; }
  };
  Own own_images(const Communicator& comm) const {
    const auto self = static_cast<std::size_t>(comm.rank());
    Own own;
    for (std::size_t r = 0; r < self; ++r) own.first += received_[r];
    own.count = received_[self];
    own.sources = send_[self].data();
    return own;
  }

  // Each send list's entries to another process, `bytes` each written by pack(i, out), and the other processes'
  // ghosts' entries back in ghost order (this process's own images left out: Own): the sizes are the ghosts' (no
  // count exchange).
  template <class Pack>
  std::vector<unsigned char> exchange_values(const Communicator& comm, std::size_t bytes, Pack&& pack) const {
    std::vector<std::size_t> send_bytes(send_.size()), receive_bytes(send_.size()), first(send_.size() + 1, 0);
    for (std::size_t r = 0; r < send_.size(); ++r) {
      const bool other = static_cast<int>(r) != comm.rank();
      send_bytes[r] = other ? send_[r].size() * bytes : 0;
      receive_bytes[r] = other ? received_[r] * bytes : 0;
      first[r + 1] = first[r] + (other ? send_[r].size() : 0);
      bytes_sent_ += send_bytes[r];
    }
    std::vector<unsigned char> send(first.back() * bytes);
    for (std::size_t r = 0; r < send_.size(); ++r)
      if (send_bytes[r] != 0)
        parallel_for(send_[r].size(), [&](std::size_t k) { pack(send_[r][k], send.data() + (first[r] + k) * bytes); });
    return comm.exchange_known(send, send_bytes, receive_bytes);
  }
  std::vector<unsigned char> exchange(const std::vector<std::vector<unsigned char>>& out, const Communicator& comm,
                                      std::vector<std::size_t>& received_bytes) const {
    std::vector<unsigned char> send;
    std::vector<std::size_t> send_bytes(out.size());
    for (std::size_t r = 0; r < out.size(); ++r) {
      send_bytes[r] = out[r].size();
      send.insert(send.end(), out[r].begin(), out[r].end());
      if (static_cast<int>(r) != comm.rank()) bytes_sent_ += out[r].size();
    }
    return comm.exchange(send, send_bytes, received_bytes);
  }

  CellPartition<D> partition_;
  std::vector<std::uint32_t> needers_first_;  // per cell, into needers_
  std::vector<int> needers_;
  std::vector<std::vector<std::uint32_t>> send_;  // per process: the owned particles whose values it receives, in order
  std::vector<std::size_t> received_;             // per process: how many ghosts came from it
  mutable std::size_t bytes_sent_ = 0;
};

}  // namespace slide
