#include "tools/shared_checkpoint.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "fluid/particle_section_head.hpp"
#include "fluid/process_halo.hpp"

namespace slide::tools {

namespace {

template <int D>
using Records = typename Simulation<D>::StateRecords;

template <int D>
ParticleId id_of(const Records<D>& r, const unsigned char* record) {
  ParticleId id;
  std::memcpy(&id, record + r.id_offset, sizeof(id));
  return id;
}

// Each record to the process of its id's range, [id_end k / P, id_end (k + 1) / P): this process's range, in id order.
template <int D>
std::vector<unsigned char> by_id_range(const Records<D>& mine, const Communicator& world) {
  const auto processes = static_cast<std::uint64_t>(world.size());
  std::int64_t id_end = mine.ids.empty() ? 0 : static_cast<std::int64_t>(mine.ids.back() + 1);
  world.max(&id_end, 1);
  std::vector<std::size_t> sizes;
  std::size_t begin = 0;
  for (std::uint64_t r = 0; r < processes; ++r) {
    const std::uint64_t bound = static_cast<std::uint64_t>(id_end) * (r + 1) / processes;
    const std::size_t end = std::lower_bound(mine.ids.begin(), mine.ids.end(), bound) - mine.ids.begin();
    sizes.push_back((end - begin) * mine.record_bytes);
    begin = end;
  }
  std::vector<std::size_t> received;
  const std::vector<unsigned char> in = world.exchange(mine.bytes, sizes, received);
  // Each sender's records are in id order; the range's are all of them, in id order.
  const std::size_t n = in.size() / mine.record_bytes;
  std::vector<std::pair<ParticleId, std::size_t>> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = {id_of<D>(mine, in.data() + k * mine.record_bytes), k};
  std::sort(order.begin(), order.end());
  std::vector<unsigned char> out(in.size());
  for (std::size_t k = 0; k < n; ++k)
    std::memcpy(out.data() + k * mine.record_bytes, in.data() + order[k].second * mine.record_bytes, mine.record_bytes);
  return out;
}

// Every process's particles that left the domain, on the first process (one exchange; a few at most).
template <int D>
std::vector<LeftParticle> left_on_first(const Simulation<D>& sim, const Communicator& world) {
  std::vector<unsigned char> mine;
  for (const LeftParticle& l : sim.left_the_domain()) {
    halo_bytes::put(mine, l.id);
    halo_bytes::put(mine, l.time);
    for (int d = 0; d < D; ++d) halo_bytes::put(mine, l.position[static_cast<std::size_t>(d)]);
  }
  std::vector<std::size_t> sizes(static_cast<std::size_t>(world.size()), 0), received;
  sizes[0] = mine.size();
  const std::vector<unsigned char> in = world.exchange(mine, sizes, received);
  std::vector<LeftParticle> left;
  for (const unsigned char* p = in.data(); p != in.data() + in.size();) {
    LeftParticle l;
    l.id = halo_bytes::get<ParticleId>(p);
    l.time = halo_bytes::get<double>(p);
    for (int d = 0; d < D; ++d) l.position.push_back(halo_bytes::get<double>(p));
    left.push_back(std::move(l));
  }
  return left;
}


// One process: its records, in id order, written a part at a time (no copy of the particles).
template <int D>
void write_records_alone(const Simulation<D>& sim, CheckpointFile& file) {
  const std::vector<std::uint32_t> order = sim.owned_in_id_order();
  constexpr std::size_t part = 65536;
  for (std::size_t begin = 0; begin == 0 || begin < order.size(); begin += part) {
    const Records<D> r = sim.state_records(order, begin, std::min(begin + part, order.size()));
    if (begin == 0) {
      StateWriter head;
      ParticleSectionHead{r.correction, r.record_bytes, order.size()}.put(head);
      file.append(head.bytes().data(), head.bytes().size());
    }
    file.append(r.bytes.data(), r.bytes.size());
  }
}

// Several processes: each process's records to the process of their id's range, then to the first one range at a
// time.
template <int D>
void write_records_shared(const Communicator& world, const Simulation<D>& sim, CheckpointFile* file) {
  std::vector<unsigned char> held;
  std::size_t record_bytes = 0;
  bool correction = false;
  {
    const Records<D> mine = sim.state_records();
    record_bytes = mine.record_bytes;
    correction = mine.correction;
    held = by_id_range<D>(mine, world);
  }
  std::int64_t particles = static_cast<std::int64_t>(held.size() / record_bytes);
  world.sum(&particles, 1);
  if (file) {
    StateWriter head;
    ParticleSectionHead{correction, record_bytes, static_cast<std::uint64_t>(particles)}.put(head);
    file->append(head.bytes().data(), head.bytes().size());
    file->append(held.data(), held.size());
  }
  const std::vector<unsigned char> none;
  for (int r = 1; r < world.size(); ++r) {  // one range at a time, in order
    const std::vector<unsigned char> range = gather_bytes_on_first(world, r == world.rank() ? held : none);
    if (file) file->append(range.data(), range.size());
  }
}

}  // namespace

template <int D>
void write_shared_checkpoint(const Communicator& world, const Simulation<D>& sim, CheckpointFile* file,
                             const StateWriter* rest) {
  if (world.size() == 1) write_records_alone(sim, *file);
  else write_records_shared(world, sim, file);
  std::vector<LeftParticle> left = left_on_first(sim, world);
  if (!file) return;
  StateWriter tail;
  Simulation<D>::put_left_particles(tail, std::move(left));
  file->append(tail.bytes().data(), tail.bytes().size());
  file->append(rest->bytes().data(), rest->bytes().size());
  file->commit();
}

template void write_shared_checkpoint(const Communicator&, const Simulation<2>&, CheckpointFile*, const StateWriter*);
template void write_shared_checkpoint(const Communicator&, const Simulation<3>&, CheckpointFile*, const StateWriter*);

}  // namespace slide::tools
