// The settling's start positions on several processes (coupling/start_positions.hpp): each process keeps those of the
// particles it owns and, after particles moved between processes, has exactly the start of each particle it now owns,
// whichever process kept it, and whether each process made its own particles or the whole scene.
#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "coupling/start_positions.hpp"
#include "tests/mpi/world.hpp"

namespace slide::testing {
namespace {

constexpr ParticleId kParticles = 40;

// Particle id's start: a place no other particle has.
Vec<3> start_of(ParticleId id) { return Vec<3>(double(id), 2.0 * double(id) + 0.5, -3.0 * double(id)); }

// The particles with ids for which `holds` is true, at `place(id)`.
template <class Holds, class Place>
Particles<3> particles_where(Holds holds, Place place) {
  Particles<3> P;
  for (ParticleId id = 0; id < kParticles; ++id)
    if (holds(id)) {
      const std::size_t i = P.add(place(id), Kind::fluid, 0, 1000.0, 1e-3);
      P.id[i] = id;
    }
  return P;
}

// Each process made every p-th particle (id % p == rank); after they moved, each owns the next process's, less the
// particles that left the domain (every 7th), and the particles have moved from their starts.
TEST(StartPositions, EachProcessGetsTheStartOfEveryParticleThatCameToIt) {
  const Communicator& comm = *world();
  const auto p = ParticleId(comm.size()), me = ParticleId(comm.rank());
  StartPositions<3> start(particles_where([&](ParticleId id) { return id % p == me; }, start_of));
  const auto owned_now = [&](ParticleId id) { return id % p == (me + 1) % p && id % 7 != 3; };
  const Particles<3> moved = particles_where(owned_now, [](ParticleId id) { return start_of(id) + Vec<3>(0.1, 0, 0); });
  start.follow(moved, &comm);
  for (ParticleId id = 0; id < kParticles; ++id)
    if (owned_now(id)) EXPECT_EQ(start.of(id), start_of(id)) << "particle " << id << " on process " << me;
  // A second move, back to where each was made: the starts follow again.
  const Particles<3> back = particles_where([&](ParticleId id) { return id % p == me && id % 7 != 3; }, start_of);
  start.follow(back, &comm);
  for (ParticleId id = me; id < kParticles; id += p)
    if (id % 7 != 3) EXPECT_EQ(start.of(id), start_of(id)) << "particle " << id << " on process " << me;
}

// Every process made the whole scene (a 2-D scene, a resumed 2-D run): each keeps its own share's starts, one copy each.
TEST(StartPositions, ProcessesThatEachMadeTheWholeSceneKeepTheirShare) {
  const Communicator& comm = *world();
  const auto p = ParticleId(comm.size()), me = ParticleId(comm.rank());
  StartPositions<3> start(particles_where([](ParticleId) { return true; }, start_of));
  const auto owned_now = [&](ParticleId id) { return (id / 3) % p == me; };
  start.follow(particles_where(owned_now, start_of), &comm);
  for (ParticleId id = 0; id < kParticles; ++id)
    if (owned_now(id)) EXPECT_EQ(start.of(id), start_of(id));
    else EXPECT_THROW(start.of(id), std::logic_error) << "particle " << id << " is another process's";
}

// Every process but the last made the whole scene and the last made none: each particle's start is sent to its id's
// home by every process but the last (copies, one kept), and the last is answered for its own.
TEST(StartPositions, CopiesOfAStartFromSeveralProcessesGiveOneAnswer) {
  const Communicator& comm = *world();
  const auto p = ParticleId(comm.size()), me = ParticleId(comm.rank());
  const bool made_all = p == 1 || me + 1 < p;
  StartPositions<3> start(particles_where([&](ParticleId) { return made_all; }, start_of));
  const auto owned_now = [&](ParticleId id) { return id % p == me; };
  start.follow(particles_where(owned_now, start_of), &comm);
  for (ParticleId id = 0; id < kParticles; ++id)
    if (owned_now(id)) EXPECT_EQ(start.of(id), start_of(id)) << "particle " << id << " on process " << me;
}

// One process: a follow drops the particles that left, and asks no one for a start it never had.
TEST(StartPositions, OneProcessDropsTheParticlesThatLeft) {
  StartPositions<3> start(particles_where([](ParticleId id) { return id < 10; }, start_of));
  start.follow(particles_where([](ParticleId id) { return id < 10 && id != 4; }, start_of), nullptr);
  EXPECT_EQ(start.of(9), start_of(9));
  EXPECT_THROW(start.of(4), std::logic_error);
  EXPECT_THROW(start.follow(particles_where([](ParticleId id) { return id == 12; }, start_of), nullptr),
               std::logic_error);
}

}  // namespace
}  // namespace slide::testing
