// The first process's whole copy of a run on several processes (coupling/simulation.hpp, adopt_whole_state).
#include <algorithm>

#include "coupling/simulation.hpp"
#include "fluid/process_halo.hpp"

namespace slide {

template <int D>
std::vector<unsigned char> Simulation<D>::owned_state_bytes() const {
  const auto& P = domain_.particles;
  const std::size_t n = P.real_count();
  std::vector<unsigned char> out;
  out.reserve(2 * sizeof(std::uint64_t) + n * (ProcessHalo<D>::record_bytes(P) + sizeof(Vec<D>)));
  halo_bytes::put<std::uint64_t>(out, n);
  halo_bytes::put<std::uint64_t>(out, left_the_domain_.size());
  halo_bytes::put<std::uint8_t>(out, correction_current_ ? 1 : 0);
  for (std::size_t i = 0; i < n; ++i) {
    ProcessHalo<D>::append_record(P, i, out);
    halo_bytes::put(out, position_at_build_[i]);
    if (correction_current_) halo_bytes::put(out, P.gradient_correction[i]);
  }
  for (const LeftParticle& l : left_the_domain_) {
    halo_bytes::put(out, l.id);
    halo_bytes::put(out, l.time);
    for (int d = 0; d < D; ++d) halo_bytes::put(out, l.position[static_cast<std::size_t>(d)]);
  }
  return out;
}

template <int D>
void Simulation<D>::adopt_whole_state(int processes, const std::function<std::vector<unsigned char>(int)>& owned_by,
                                      const Simulation& running) {
  if (domain_.distributed()) throw std::logic_error("adopt_whole_state on a simulation that runs on several processes");
  auto& P = domain_.particles;
  const std::size_t made = P.id_end();
  domain_.drop_ghosts();
  P.for_each_array([](auto& v) { v.clear(); });
  P.gradient_correction.clear();
  position_at_build_.clear();
  left_the_domain_.clear();
  bool correction = false;  // the same on every process
  for (int r = 0; r < processes; ++r) {  // one process's particles at a time: no buffer holds the whole scene
    const std::vector<unsigned char> piece = owned_by(r);
    const unsigned char* in = piece.data();
    if (piece.empty()) continue;
    const auto n = halo_bytes::get<std::uint64_t>(in), left = halo_bytes::get<std::uint64_t>(in);
    correction = halo_bytes::get<std::uint8_t>(in) != 0;
    for (std::uint64_t k = 0; k < n; ++k) {
      ProcessHalo<D>::read_record(P, in);
      position_at_build_.push_back(halo_bytes::get<Vec<D>>(in));
      if (correction) P.gradient_correction.push_back(halo_bytes::get<Mat<D>>(in));
    }
    for (std::uint64_t k = 0; k < left; ++k) {
      LeftParticle l;
      l.id = halo_bytes::get<ParticleId>(in);
      l.time = halo_bytes::get<double>(in);
      for (int d = 0; d < D; ++d) l.position.push_back(halo_bytes::get<double>(in));
      left_the_domain_.push_back(std::move(l));
    }
  }
  if (P.real_count() > made) throw std::logic_error("adopt_whole_state: more particles than the scene made");
  P.removed_count = made - P.real_count();
  // One process records them step by step, by id within a step.
  std::sort(left_the_domain_.begin(), left_the_domain_.end(), [](const LeftParticle& a, const LeftParticle& b) {
    return a.time < b.time || (a.time == b.time && a.id < b.id);
  });
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
  if (domain_.make_ghosts(list_radius())) {
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

template std::vector<unsigned char> Simulation<2>::owned_state_bytes() const;
template std::vector<unsigned char> Simulation<3>::owned_state_bytes() const;
template void Simulation<2>::adopt_whole_state(int, const std::function<std::vector<unsigned char>(int)>&,
                                               const Simulation<2>&);
template void Simulation<3>::adopt_whole_state(int, const std::function<std::vector<unsigned char>(int)>&,
                                               const Simulation<3>&);

}  // namespace slide
