#pragma once
// The head of a checkpoint state's particle section (Simulation::restore_state; tools/checkpoint.hpp): u8 whether
// the records hold gradient matrices, u64 a record's bytes, u64 the records that follow. Written here and read here,
// by the whole state's reader and by the reader of a process's part of the file alike.
#include <cstdint>

#include "fluid/state_stream.hpp"

namespace slide {

struct ParticleSectionHead {
  bool correction = false;  // the records hold gradient matrices
  std::uint64_t record_bytes = 0;
  std::uint64_t particles = 0;

  void put(StateWriter& out) const {
    out.put<std::uint8_t>(correction ? 1 : 0);
    out.put(record_bytes);
    out.put(particles);
  }
  // From any reader with get<T>() (a StateReader, or the checkpoint file's bytes).
  template <class Reader>
  static ParticleSectionHead get(Reader& in) {
    ParticleSectionHead h;
    h.correction = in.template get<std::uint8_t>() != 0;
    h.record_bytes = in.template get<std::uint64_t>();
    h.particles = in.template get<std::uint64_t>();
    return h;
  }
};

}  // namespace slide
