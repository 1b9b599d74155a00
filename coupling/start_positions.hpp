#pragma once
// Where each real particle started settling, by id (coupling/relaxation.hpp: a held slide's particles go back to it
// after every step, and the largest shift is measured from it). On several processes each keeps the start of the
// particles it owns and, after particles have moved between processes (a re-sort), fetches the start of those that
// came to it from the process that kept it (`follow`, a collective). Before (stop 62), every process gathered every
// particle's id and start (8 + 8 D bytes a particle) and kept the whole scene's starts (8 D bytes a particle): memory
// that grew with the scene however many processes shared it. Now a process keeps its own (8 + 8 D bytes an owned
// particle), and a follow holds the ids of the particles that moved between processes since the last one (8 bytes
// each, on every process: after a scene built in parts, its first follow lists most particles).
#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "fluid/communicator.hpp"
#include "fluid/particles.hpp"
#include "fluid/process_halo.hpp"

namespace slide {

template <int D>
class StartPositions {
 public:
  // The real particles P holds now: on several processes before the scene is shared among them, those this process
  // made (all of them, where every process makes the whole scene).
  explicit StartPositions(const Particles<D>& P) {
    records_.reserve(P.real_count());
    for (std::size_t i = 0; i < P.real_count(); ++i) records_.push_back({P.id[i], P.position[i]});
    sort_by_id(records_);
  }

  // Keeps the starts of the particles P owns, fetching those it lacks from the processes that have them (comm: null
  // on one process, where it only drops the starts of particles that left the domain). Every process calls it at the
  // same point.
  void follow(const Particles<D>& P, const Communicator* comm) {
    std::vector<ParticleId> owned(P.id.begin(), P.id.begin() + static_cast<std::ptrdiff_t>(P.real_count()));
    std::sort(owned.begin(), owned.end());
    std::vector<Record> kept;
    kept.reserve(owned.size());
    std::vector<ParticleId> missing;
    for (const ParticleId id : owned) {
      if (const Record* r = find(id)) kept.push_back(*r);
      else missing.push_back(id);
    }
    std::int64_t lacking = static_cast<std::int64_t>(missing.size());
    if (comm) comm->sum(&lacking, 1);
    if (lacking > 0) {
      if (!comm) throw std::logic_error("StartPositions::follow: a particle without its start on one process");
      fetch(missing, *comm, kept);
    }
    if (kept.size() != owned.size())
      throw std::logic_error("StartPositions::follow: a particle's start was kept by no process");
    records_.swap(kept);
  }

  // The start of a particle this process owns (since the last follow).
  const Vec<D>& of(ParticleId id) const {
    const Record* r = find(id);
    if (!r) throw std::logic_error("StartPositions::of: a particle without its start");
    return r->position;
  }

 private:
  struct Record {
    ParticleId id;
    Vec<D> position;
  };
  static void sort_by_id(std::vector<Record>& v) {
    std::sort(v.begin(), v.end(), [](const Record& a, const Record& b) { return a.id < b.id; });
  }
  const Record* find(ParticleId id) const {
    const auto r = std::lower_bound(records_.begin(), records_.end(), id,
                                    [](const Record& a, ParticleId b) { return a.id < b; });
    return r != records_.end() && r->id == id ? &*r : nullptr;
  }

  // Every process's missing ids go to every process; each answers with the starts it has of them. Where several have
  // one (every process made the whole scene), the copies are the same: one is kept.
  void fetch(const std::vector<ParticleId>& missing, const Communicator& comm, std::vector<Record>& kept) const {
    const auto processes = static_cast<std::size_t>(comm.size());
    std::vector<unsigned char> mine;
    for (const ParticleId id : missing) halo_bytes::put(mine, id);
    std::vector<unsigned char> asks;
    for (std::size_t r = 0; r < processes; ++r) asks.insert(asks.end(), mine.begin(), mine.end());
    std::vector<std::size_t> asked_bytes;
    const std::vector<unsigned char> asked =
        comm.exchange(asks, std::vector<std::size_t>(processes, mine.size()), asked_bytes);
    std::vector<unsigned char> answers;
    std::vector<std::size_t> answer_bytes(processes, 0);
    const unsigned char* in = asked.data();
    for (std::size_t r = 0; r < processes; ++r) {
      const std::size_t before = answers.size();
      for (std::size_t k = 0; k < asked_bytes[r] / sizeof(ParticleId); ++k)
        if (const Record* found = find(halo_bytes::get<ParticleId>(in)); found && r != std::size_t(comm.rank())) {
          halo_bytes::put(answers, found->id);
          halo_bytes::put(answers, found->position);
        }
      answer_bytes[r] = answers.size() - before;
    }
    std::vector<std::size_t> received_bytes;
    const std::vector<unsigned char> received = comm.exchange(answers, answer_bytes, received_bytes);
    constexpr std::size_t record = sizeof(ParticleId) + sizeof(Vec<D>);
    for (const unsigned char *q = received.data(), *end = q + received.size(); q + record <= end;) {
      const auto id = halo_bytes::get<ParticleId>(q);
      kept.push_back({id, halo_bytes::get<Vec<D>>(q)});
    }
    sort_by_id(kept);
    kept.erase(std::unique(kept.begin(), kept.end(), [](const Record& a, const Record& b) { return a.id == b.id; }),
               kept.end());
  }

  std::vector<Record> records_;  // sorted by id
};

}  // namespace slide
