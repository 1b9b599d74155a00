#pragma once
// Checkpoints: DIR/checkpoint.bin holds what `slide run --resume DIR` needs to continue a run so that every snapshot
// and CSV it writes is bit-identical to the straight run's, with any thread count: the scene it was made from, and the
// state of the simulation (coupling/simulation.hpp, save_state: particles, neighbour-list state, counters, bodies
// with Bullet's world as its journal) and of the outputs (tools/run_outputs.hpp). A run writes one at the scene's
// output.checkpoint_interval and when it is interrupted (SIGINT, SIGTERM).
//
// Layout: "SLIDECKP", a format number, the header's bytes (fluid/state_stream.hpp), the state's bytes to the end, and
// an FNV-1a hash of all that, so a torn or edited file is refused rather than half read. Written atomically, in parts
// where the state comes from several processes (tools/shared_checkpoint.hpp).
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/atomic_file.hpp"

namespace slide::tools {

// What a checkpoint's header names as its writer: slide's version and the format of the simulation's saved state. The
// format's number changes with the state it holds (2: the corrected gradient's matrices, issue 29; 3: a checkpoint
// can be taken while settling, issue 30; 4: a solid body's journal holds its convex pieces, issue 31), so that a
// checkpoint of another format is refused as such rather than misread (a format-1 checkpoint was refused as "the
// checkpoint's bodies are not the scene's").
inline std::string checkpoint_writer() { return std::string(SLIDE_VERSION) + ", state format 4"; }

struct CheckpointHeader {
  std::string version;         // checkpoint_writer() of the program that wrote it
  std::string scene_file;      // as given to slide run
  std::vector<std::string> overrides;  // --set, in order
  std::string resolved_scene;  // the scene with every default filled in, as YAML: what the state belongs to
  double time = 0.0;           // s, the run's time at the checkpoint (the settling's, when settling)
  long step = 0;
  // Taken while the water settled before t = 0 (a signal stopped it there): the state is the simulation's and the
  // settling's (coupling/relaxation.hpp, Settling), and a resumed run settles on from it, then runs.
  bool settling = false;
};

struct Checkpoint {
  CheckpointHeader header;
  std::vector<char> state;
};

// A checkpoint that cannot be used; the message says why (missing, damaged, another version).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::filesystem::path checkpoint_path(const std::filesystem::path& run_dir);
void write_checkpoint(const std::filesystem::path& run_dir, const Checkpoint& checkpoint);

// checkpoint.bin written as its state comes: the header, the state's parts in order, then (commit) the checksum.
class CheckpointFile {
 public:
  CheckpointFile(const std::filesystem::path& run_dir, const CheckpointHeader& header);
  void append(const void* data, std::size_t bytes);
  void commit();

 private:
  AtomicFileWriter file_;
  std::uint64_t hash_;
};
// Throws CheckpointError when the file is missing, damaged or of another format; the version is for the caller to
// compare (it names both).
Checkpoint read_checkpoint(const std::filesystem::path& run_dir);
// The header alone (the checksum not checked): what decides how the state is read.
CheckpointHeader read_checkpoint_header(const std::filesystem::path& run_dir);
// Part `part` of `parts` of a checkpoint, for a run resumed on several processes that each take a part of its
// particles (tools/run_driver.cpp): its state holds the records [particles * part / parts, particles * (part + 1) /
// parts) of the particle section (coupling/simulation.hpp, restore_state) and the whole of the rest, so that no
// process reads the whole scene's particles. `verify`: the whole file's checksum checked too, reading it through a
// MiB at a time (one process does, and the others take its word). read_checkpoint is part 0 of 1, verified.
Checkpoint read_checkpoint_part(const std::filesystem::path& run_dir, std::uint64_t part, std::uint64_t parts,
                                bool verify);

}  // namespace slide::tools
