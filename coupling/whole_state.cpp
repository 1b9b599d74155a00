// The first process's whole copy of a run on several processes (coupling/simulation.hpp, adopt_whole_state).
#include <algorithm>
#include <numeric>

#include "coupling/simulation.hpp"
#include "fluid/particle_section_head.hpp"
#include "fluid/process_halo.hpp"

namespace slide {

template <int D>
void Simulation<D>::append_state_record(std::size_t i, bool correction, std::vector<unsigned char>& out) const {
  ProcessHalo<D>::append_record(domain_.particles, i, out);
  halo_bytes::put(out, position_at_build_[i]);
  if (correction) halo_bytes::put(out, domain_.particles.gradient_correction[i]);
}

template <int D>
void Simulation<D>::read_state_record(const unsigned char*& in, bool correction) {
  ProcessHalo<D>::read_record(domain_.particles, in);
  position_at_build_.push_back(halo_bytes::get<Vec<D>>(in));
  if (correction) domain_.particles.gradient_correction.push_back(halo_bytes::get<Mat<D>>(in));
}

template <int D>
std::vector<unsigned char> Simulation<D>::owned_state_bytes(const std::function<bool(std::size_t)>& read) const {
  const auto& P = domain_.particles;
  const std::size_t n = P.real_count();
  std::vector<std::uint32_t> sent;
  sent.reserve(read ? 0 : n);
  for (std::size_t i = 0; i < n; ++i)
    if (!read || read(i)) sent.push_back(static_cast<std::uint32_t>(i));
  std::vector<unsigned char> out;
  out.reserve(3 * sizeof(std::uint64_t) + 1 + sent.size() * (ProcessHalo<D>::record_bytes(P) + sizeof(Vec<D>)));
  halo_bytes::put<std::uint64_t>(out, n);
  halo_bytes::put<std::uint64_t>(out, sent.size());
  halo_bytes::put<std::uint64_t>(out, left_the_domain_.size());
  halo_bytes::put<std::uint8_t>(out, correction_current_ ? 1 : 0);
  for (const std::uint32_t i : sent) append_state_record(i, correction_current_, out);
  for (const LeftParticle& l : left_the_domain_) {
    halo_bytes::put(out, l.id);
    halo_bytes::put(out, l.time);
    for (int d = 0; d < D; ++d) halo_bytes::put(out, l.position[static_cast<std::size_t>(d)]);
  }
  return out;
}

// Empties the particles (ghosts, build positions, gradient matrices, left particles) for records to be read in.
template <int D>
void clear_particles(Particles<D>& P, std::vector<Vec<D>>& position_at_build, std::vector<LeftParticle>& left) {
  P.for_each_array([](auto& v) { v.clear(); });
  P.gradient_correction.clear();
  position_at_build.clear();
  left.clear();
}

template <int D>
void Simulation<D>::adopt_whole_state(int processes, const std::function<std::vector<unsigned char>(int)>& owned_by,
                                      const Simulation& running) {
  if (domain_.distributed()) throw std::logic_error("adopt_whole_state on a simulation that runs on several processes");
  auto& P = domain_.particles;
  const std::size_t made = P.id_end();
  domain_.drop_ghosts();
  clear_particles(P, position_at_build_, left_the_domain_);
  bool correction = false;  // the same on every process
  particles_in_run_ = 0;
  for (int r = 0; r < processes; ++r) {  // one process's particles at a time: no buffer holds the whole scene
    const std::vector<unsigned char> piece = owned_by(r);
    const unsigned char* in = piece.data();
    if (piece.empty()) continue;
    particles_in_run_ += halo_bytes::get<std::uint64_t>(in);
    const auto n = halo_bytes::get<std::uint64_t>(in), left = halo_bytes::get<std::uint64_t>(in);
    correction = halo_bytes::get<std::uint8_t>(in) != 0;
    for (std::uint64_t k = 0; k < n; ++k) read_state_record(in, correction);
    for (std::uint64_t k = 0; k < left; ++k) {
      LeftParticle l;
      l.id = halo_bytes::get<ParticleId>(in);
      l.time = halo_bytes::get<double>(in);
      for (int d = 0; d < D; ++d) l.position.push_back(halo_bytes::get<double>(in));
      left_the_domain_.push_back(std::move(l));
    }
  }
  if (particles_in_run_ > made) throw std::logic_error("adopt_whole_state: more particles than the scene made");
  P.removed_count = made - P.real_count();  // the id range stays the run's
  // One process records them step by step, by id within a step.
  std::sort(left_the_domain_.begin(), left_the_domain_.end(), [](const LeftParticle& a, const LeftParticle& b) {
    return a.time < b.time || (a.time == b.time && a.id < b.id);
  });
  store_as_one_process(correction);
  time_ = running.time_;
  step_count_ = running.step_count_;
  limit_counts_ = running.limit_counts_;
  largest_number_density_ratio_ = running.largest_number_density_ratio_;
  largest_number_density_ratio_time_ = running.largest_number_density_ratio_time_;
  rebuilds_ = running.rebuilds_;
  viscous_solves_ = running.viscous_solves_;
  last_viscous_solve_ = running.last_viscous_solve_;
  options.velocity_damping_rate = running.options.velocity_damping_rate;
  rheology_suspended_ = running.rheology_suspended_;
  // The bodies are the same on every process (each steps its own copy of the rigid world with the same combined
  // forces): the copy reads the running simulation's.
  if (bodies_ || running.bodies_) bodies_ = running.bodies_;
}

template <int D>
void Simulation<D>::drop_copy_particles() {
  if (!observers_copy_) throw std::logic_error("drop_copy_particles on a running simulation");
  auto& P = domain_.particles;
  const std::size_t made = P.id_end();
  domain_.drop_ghosts();
  clear_particles(P, position_at_build_, left_the_domain_);
  P.for_each_array([](auto& v) { v.shrink_to_fit(); });
  P.gradient_correction.shrink_to_fit();
  position_at_build_.shrink_to_fit();
  list_ = NeighborList{};
  P.removed_count = made;
  particles_in_run_ = made;
}

// A resumed run on several processes (restore_state): each process read a part of the checkpoint's particles; each
// particle goes whole (its record: every array, its position at the last re-sort, its gradient matrix) to the process
// of its cell at its position of the last re-sort, the cells shared out anew by those positions, as the processes
// of the saved run would hold it at its next re-sort (distribute does the same from the whole state).
template <int D>
void Simulation<D>::share_restored_particles(bool correction) {
  auto& P = domain_.particles;
  const Communicator& comm = *domain_.communicator();
  domain_.share_cells_by(grid_, position_at_build_, [&] {
    const std::size_t record = ProcessHalo<D>::record_bytes(P) + sizeof(Vec<D>) + (correction ? sizeof(Mat<D>) : 0);
    const auto processes = static_cast<std::size_t>(comm.size());
    std::vector<std::vector<std::uint32_t>> to(processes);  // the particles each process takes, in id order
    for (std::size_t i = 0; i < P.real_count(); ++i)
      to[static_cast<std::size_t>(domain_.owner_of_point(position_at_build_[i], grid_))].push_back(std::uint32_t(i));
    std::vector<unsigned char> send;
    send.reserve(P.real_count() * record);
    std::vector<std::size_t> send_bytes(processes), received_bytes;
    for (std::size_t r = 0; r < processes; ++r) {
      for (const std::uint32_t i : to[r]) append_state_record(i, correction, send);
      send_bytes[r] = to[r].size() * record;
    }
    const std::vector<unsigned char> in = comm.exchange(send, send_bytes, received_bytes);
    std::vector<LeftParticle> left = std::move(left_the_domain_);
    clear_particles(P, position_at_build_, left_the_domain_);
    left_the_domain_ = std::move(left);
    const unsigned char* q = in.data();
    for (std::size_t k = 0; k < in.size() / record; ++k) read_state_record(q, correction);
  });
}

template <int D>
void Simulation<D>::store_as_one_process(bool correction) {
  auto& P = domain_.particles;
  // Re-sorted as the last re-sort left them, the ghosts and the list made from those positions (update_neighbors),
  // then the present positions and the ghosts' fields.
  std::vector<Vec<D>> now = P.position;
  P.position = position_at_build_;
  const auto key = [&P](std::uint32_t j) { return P.order_key(j); };
  grid_.bin(P.position, key);
  const std::vector<std::uint32_t>& order = grid_.sorted_indices();
  std::vector<Vec<D>> now_sorted(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) now_sorted[k] = now[order[k]];
  if (correction) {
    const std::vector<Mat<D>> gathered_correction = P.gradient_correction;
    for (std::size_t k = 0; k < order.size(); ++k) P.gradient_correction[k] = gathered_correction[order[k]];
  }
  scratch_.resize(P.size(), Vec<D>::Zero());
  P.reorder(order, scratch_);
  if (domain_.make_ghosts(list_radius(), grid_)) {
    scratch_.resize(P.size(), Vec<D>::Zero());
    grid_.bin(P.position, key);
  } else {
    grid_.follow_reorder();
  }
  if (!observers_copy_ || copy_lists_) build_neighbor_list(grid_, P.position, list_radius(), list_, P.real_count());
  position_at_build_ = P.position;
  std::copy(now_sorted.begin(), now_sorted.end(), P.position.begin());
  domain_.refresh({HaloField::motion, HaloField::number_density, HaloField::pressure, HaloField::viscosity,
                   HaloField::wall_fraction, HaloField::wall_fill, HaloField::wall_normal});
  if (correction) {
    P.gradient_correction.resize(P.size());
    domain_.refresh({HaloField::gradient_correction});
  }
  pair_weights_.forget();
  correction_current_ = correction;
}

template <int D>
std::vector<std::uint32_t> Simulation<D>::owned_in_id_order() const {
  const auto& P = domain_.particles;
  std::vector<std::uint32_t> order(P.real_count());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&P](std::uint32_t a, std::uint32_t b) { return P.id[a] < P.id[b]; });
  return order;
}

template <int D>
typename Simulation<D>::StateRecords Simulation<D>::state_records(const std::vector<std::uint32_t>& order,
                                                                  std::size_t begin, std::size_t end) const {
  const auto& P = domain_.particles;
  StateRecords r;
  r.correction = correction_current_;
  r.record_bytes = ProcessHalo<D>::record_bytes(P) + sizeof(Vec<D>) + (r.correction ? sizeof(Mat<D>) : 0);
  bool past_id = false;
  P.for_each_array([&](const auto& v) {
    if (static_cast<const void*>(&v) == static_cast<const void*>(&P.id)) past_id = true;
    if (!past_id) r.id_offset += sizeof(typename std::decay_t<decltype(v)>::value_type);
  });
  r.bytes.reserve((end - begin) * r.record_bytes);
  r.ids.reserve(end - begin);
  for (std::size_t k = begin; k < end; ++k) {
    append_state_record(order[k], r.correction, r.bytes);
    r.ids.push_back(P.id[order[k]]);
  }
  return r;
}

template <int D>
typename Simulation<D>::StateRecords Simulation<D>::state_records() const {
  const std::vector<std::uint32_t> order = owned_in_id_order();
  return state_records(order, 0, order.size());
}

template <int D>
void Simulation<D>::put_left_particles(StateWriter& out, std::vector<LeftParticle> left) {
  std::sort(left.begin(), left.end(), [](const LeftParticle& a, const LeftParticle& b) {
    return a.time < b.time || (a.time == b.time && a.id < b.id);
  });
  out.put<std::uint64_t>(left.size());
  for (const auto& l : left) {
    out.put(l.id);
    out.put(l.time);
    out.put(l.position);
  }
}

// The particle section (restore_state) read back in id order, of a scene of `made` particles (on several processes:
// this process's part of it); returns whether it holds gradient matrices.
template <int D>
bool Simulation<D>::read_particle_section(StateReader& in, std::size_t made) {
  auto& P = domain_.particles;
  const ParticleSectionHead head = ParticleSectionHead::get(in);
  const bool correction = head.correction;
  const std::uint64_t record_bytes = head.record_bytes, particles = head.particles;
  const std::size_t expected = ProcessHalo<D>::record_bytes(P) + sizeof(Vec<D>) + (correction ? sizeof(Mat<D>) : 0);
  if (record_bytes != expected || particles > made)
    throw std::runtime_error("the checkpoint's particles are not the scene's");
  if (particles > in.remaining() / record_bytes) throw std::runtime_error("the state is truncated");
  domain_.drop_ghosts();
  clear_particles(P, position_at_build_, left_the_domain_);
  const unsigned char* records = in.take_bytes(particles * record_bytes);
  for (std::uint64_t k = 0; k < particles; ++k) read_state_record(records, correction);
  for (std::uint64_t k = 0; k < particles; ++k)
    if (P.id[k] >= made || (k > 0 && P.id[k] <= P.id[k - 1]))
      throw std::runtime_error("the checkpoint's particles are not the scene's");
  const bool shared = domain_.distributed();
  P.removed_count = shared ? 0 : made - particles;  // (several processes: the others hold them)
  left_the_domain_.resize(in.get<std::uint64_t>());
  for (auto& l : left_the_domain_) {
    in.get(l.id);
    in.get(l.time);
    in.get(l.position);
  }
  if (shared && domain_.communicator()->rank() > 0) left_the_domain_.clear();  // the first's to report, once
  return correction;
}

template std::vector<unsigned char> Simulation<2>::owned_state_bytes(const std::function<bool(std::size_t)>&) const;
template std::vector<unsigned char> Simulation<3>::owned_state_bytes(const std::function<bool(std::size_t)>&) const;
template void Simulation<2>::drop_copy_particles();
template void Simulation<3>::drop_copy_particles();
template void Simulation<2>::adopt_whole_state(int, const std::function<std::vector<unsigned char>(int)>&,
                                               const Simulation<2>&);
template void Simulation<3>::adopt_whole_state(int, const std::function<std::vector<unsigned char>(int)>&,
                                               const Simulation<3>&);

}  // namespace slide
