#pragma once
// Where each real particle started settling, by id (coupling/relaxation.hpp: a held slide's particles go back to it
// after every step, and the largest shift is measured from it). On several processes each keeps the start of the
// particles it owns and, after particles have moved between processes (a re-sort), fetches the start of those that
// came to it from the process that kept it (`follow`, a collective). Before (stop 62), every process gathered every
// particle's id and start (8 + 8 D bytes a particle) and kept the whole scene's starts (8 D bytes a particle): memory
// that grew with the scene however many processes shared it. Now a process keeps its own (8 + 8 D bytes an owned
// particle); at a follow the starts of particles that left a process go to the process of their id's range, which
// answers the processes they came to: each buffer holds a part of the particles that moved (until stop 64 every
// process received every moved particle's id, 8 bytes each, most particles after a scene built in parts).
#include <algorithm>
#include <cstddef>
#include <cstdint>
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
    std::vector<Record> kept, leavers;  // the starts of particles owned, and of those no longer owned here
    kept.reserve(owned.size());
    std::vector<ParticleId> missing;
    auto o = owned.begin();
    for (const Record& r : records_) {
      for (; o != owned.end() && *o < r.id; ++o) missing.push_back(*o);
      if (o != owned.end() && *o == r.id) {
        kept.push_back(r);
        ++o;
      } else {
        leavers.push_back(r);
      }
    }
    missing.insert(missing.end(), o, owned.end());
    std::int64_t lacking = static_cast<std::int64_t>(missing.size());
    if (comm) comm->sum(&lacking, 1);
    if (lacking > 0) {
      if (!comm) throw std::logic_error("StartPositions::follow: a particle without its start on one process");
      fetch(missing, leavers, *comm, kept);
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

  // The starts that left a process go to the process of their id's range (their home: ids [k N / P, (k + 1) N / P)
  // for ids below N), the missing ids ask their homes, and each home answers with what it was given: every buffer holds
  // a part of the particles that moved, none the whole scene's. Where several processes sent one (every process made
  // the whole scene), the copies are the same: one is kept.
  void fetch(const std::vector<ParticleId>& missing, const std::vector<Record>& leavers, const Communicator& comm,
             std::vector<Record>& kept) const {
    const auto processes = static_cast<std::size_t>(comm.size());
    std::int64_t end = 0;  // past every id held or owned anywhere
    if (!leavers.empty()) end = std::max<std::int64_t>(end, std::int64_t(leavers.back().id) + 1);
    if (!missing.empty()) end = std::max<std::int64_t>(end, std::int64_t(missing.back()) + 1);
    comm.max(&end, 1);
    const auto home = [&](ParticleId id) {
      using Wide = unsigned __int128;
      return static_cast<std::size_t>(Wide(id) * processes / static_cast<std::uint64_t>(end));
    };
    const std::vector<Record> given = sorted_unique(exchange_by_home(leavers, home, comm));
    // What each process asks, by asker: answered in the order asked.
    std::vector<std::size_t> asked_bytes;
    const std::vector<unsigned char> asked = exchange_ids(missing, home, comm, asked_bytes);
    std::vector<unsigned char> answers;
    std::vector<std::size_t> answer_bytes(processes, 0);
    const unsigned char* in = asked.data();
    for (std::size_t r = 0; r < processes; ++r) {
      const std::size_t before = answers.size();
      for (std::size_t k = 0; k < asked_bytes[r] / sizeof(ParticleId); ++k) {
        const auto id = halo_bytes::get<ParticleId>(in);
        const auto g = std::lower_bound(given.begin(), given.end(), id,
                                        [](const Record& a, ParticleId b) { return a.id < b; });
        if (g == given.end() || g->id != id) continue;  // (kept by no process: follow says so)
        halo_bytes::put(answers, g->id);
        halo_bytes::put(answers, g->position);
      }
      answer_bytes[r] = answers.size() - before;
    }
    std::vector<std::size_t> received_bytes;
    const std::vector<unsigned char> received = comm.exchange(answers, answer_bytes, received_bytes);
    for (const unsigned char *q = received.data(), *stop = q + received.size(); q + kRecordBytes <= stop;) {
      const auto id = halo_bytes::get<ParticleId>(q);
      kept.push_back({id, halo_bytes::get<Vec<D>>(q)});
    }
    sort_by_id(kept);
  }

  static constexpr std::size_t kRecordBytes = sizeof(ParticleId) + sizeof(Vec<D>);
  static std::vector<Record> sorted_unique(std::vector<Record> v) {
    sort_by_id(v);
    v.erase(std::unique(v.begin(), v.end(), [](const Record& a, const Record& b) { return a.id == b.id; }), v.end());
    return v;
  }
  // Records sorted by id, each to its id's home (the homes rise with the ids: the buffer is in the processes' order, as
  // the exchange takes it); returns those this process was sent.
  template <class Home>
  static std::vector<Record> exchange_by_home(const std::vector<Record>& records, Home&& home,
                                              const Communicator& comm) {
    std::vector<unsigned char> send;
    std::vector<std::size_t> send_bytes(static_cast<std::size_t>(comm.size()), 0), received_bytes;
    for (const Record& r : records) {
      halo_bytes::put(send, r.id);
      halo_bytes::put(send, r.position);
      send_bytes[home(r.id)] += kRecordBytes;
    }
    const std::vector<unsigned char> in = comm.exchange(send, send_bytes, received_bytes);
    std::vector<Record> out(in.size() / kRecordBytes);
    const unsigned char* q = in.data();
    for (Record& r : out) {
      r.id = halo_bytes::get<ParticleId>(q);
      r.position = halo_bytes::get<Vec<D>>(q);
    }
    return out;
  }
  // Ids sorted, each to its home (as above); returns what every process asked this one, by asker (asked_bytes).
  template <class Home>
  static std::vector<unsigned char> exchange_ids(const std::vector<ParticleId>& ids, Home&& home,
                                                 const Communicator& comm, std::vector<std::size_t>& asked_bytes) {
    std::vector<unsigned char> send;
    std::vector<std::size_t> send_bytes(static_cast<std::size_t>(comm.size()), 0);
    for (const ParticleId id : ids) {
      halo_bytes::put(send, id);
      send_bytes[home(id)] += sizeof(ParticleId);
    }
    return comm.exchange(send, send_bytes, asked_bytes);
  }

  std::vector<Record> records_;  // sorted by id
};

}  // namespace slide
