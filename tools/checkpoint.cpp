#include "tools/checkpoint.hpp"

#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "fluid/state_stream.hpp"

namespace slide::tools {

namespace {

constexpr char kMagic[8] = {'S', 'L', 'I', 'D', 'E', 'C', 'K', 'P'};
// 2: body particles' frames in a table of their own (stop 25); 3: slide_shapes.csv; 4: the header says whether it was
// taken while settling (issue 30); 5: ghosts as a flip and an offset (mirror images, stop 42); 6: the rigid journal's
// solids say whether they are kinematic (3-D prescribed motion, stop 43); 7: particle ids are 64-bit (issue 32); 8: a
// ghost carries its source's id (issue 32); 9: the particles in id order without their ghosts, the state to the end
// of the file (issue 32: a checkpoint written from every process's own particles).
constexpr std::uint32_t kFormat = 9;

// FNV-1a, 64 bits: enough to tell a torn or altered file, not a guard against tampering. `h`: the hash of what came
// before (a file hashed in parts).
constexpr std::uint64_t kFnvStart = 1469598103934665603ull;
std::uint64_t fnv1a(const char* data, std::size_t n, std::uint64_t h = kFnvStart) {
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

std::filesystem::path checkpoint_path(const std::filesystem::path& run_dir) { return run_dir / "checkpoint.bin"; }

CheckpointFile::CheckpointFile(const std::filesystem::path& run_dir, const CheckpointHeader& header)
    : file_(checkpoint_path(run_dir)), hash_(kFnvStart) {
  StateWriter w;
  for (char ch : kMagic) w.put(ch);
  w.put(kFormat);
  w.put(header.version);
  w.put(header.scene_file);
  w.put<std::uint64_t>(header.overrides.size());
  for (const auto& o : header.overrides) w.put(o);
  w.put(header.resolved_scene);
  w.put(header.time);
  w.put(header.step);
  w.put<std::uint8_t>(header.settling ? 1 : 0);
  append(w.bytes().data(), w.bytes().size());
}

void CheckpointFile::append(const void* data, std::size_t bytes) {
  hash_ = fnv1a(static_cast<const char*>(data), bytes, hash_);
  file_.append(std::string_view(static_cast<const char*>(data), bytes));
}

void CheckpointFile::commit() {
  file_.append(std::string_view(reinterpret_cast<const char*>(&hash_), sizeof(hash_)));
  file_.commit();
}

void write_checkpoint(const std::filesystem::path& run_dir, const Checkpoint& c) {
  CheckpointFile file(run_dir, c.header);
  file.append(c.state.data(), c.state.size());
  file.commit();
}

Checkpoint read_checkpoint(const std::filesystem::path& run_dir) {
  const auto path = checkpoint_path(run_dir);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(fmt::format("no checkpoint in {} ({} cannot be read)", run_dir.string(), path.string()));
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t body = bytes.size() >= sizeof(std::uint64_t) ? bytes.size() - sizeof(std::uint64_t) : 0;
  std::uint64_t stored = 0;
  if (bytes.size() >= sizeof(kMagic) + sizeof(stored)) std::memcpy(&stored, bytes.data() + body, sizeof(stored));
  if (bytes.size() < sizeof(kMagic) + sizeof(stored) || !std::equal(kMagic, kMagic + 8, bytes.begin()))
    throw CheckpointError(fmt::format("{} is not a slide checkpoint", path.string()));
  if (fnv1a(bytes.data(), body) != stored)
    throw CheckpointError(fmt::format("{} is damaged (its checksum does not match: truncated or altered)", path.string()));
  bytes.resize(body);  // the checksum off
  StateReader r(bytes);
  try {
    for (std::size_t k = 0; k < sizeof(kMagic); ++k) r.get<char>();
    if (const auto format = r.get<std::uint32_t>(); format != kFormat)
      throw CheckpointError(fmt::format("{} has checkpoint format {}, this slide reads format {}", path.string(), format,
                                        kFormat));
    Checkpoint c;
    r.get(c.header.version);
    r.get(c.header.scene_file);
    c.header.overrides.resize(r.get<std::uint64_t>());
    for (auto& o : c.header.overrides) r.get(o);
    r.get(c.header.resolved_scene);
    r.get(c.header.time);
    r.get(c.header.step);
    c.header.settling = r.get<std::uint8_t>() != 0;
    const std::size_t state = r.remaining();
    const unsigned char* from = r.take_bytes(state);
    c.state.assign(from, from + state);
    return c;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw CheckpointError(fmt::format("{} is damaged: {}", path.string(), e.what()));
  }
}

}  // namespace slide::tools
