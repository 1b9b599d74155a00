#include "tools/checkpoint.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "fluid/particle_section_head.hpp"
#include "fluid/state_stream.hpp"

namespace slide::tools {

namespace {

constexpr char kMagic[8] = {'S', 'L', 'I', 'D', 'E', 'C', 'K', 'P'};
// 2: body particles' frames in a table of their own (stop 25); 3: slide_shapes.csv; 4: the header says whether it was
// taken while settling (issue 30); 5: ghosts as a flip and an offset (mirror images, stop 42); 6: the rigid journal's
// solids say whether they are kinematic (3-D prescribed motion, stop 43); 7: particle ids are 64-bit (issue 32); 8: a
// ghost carries its source's id (issue 32); 9: the particles in id order without their ghosts, the state to the end
// of the file (issue 32: a checkpoint written from every process's own particles); 10: a checkpoint taken while
// settling says whether its last check found the water not at rest (stop 65).
constexpr std::uint32_t kFormat = 10;

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

namespace {

// The file's bytes before its checksum, read where asked: what a part of a checkpoint needs without the whole in
// memory. A read past them is a damaged file's (runtime_error, which read_checkpoint_part names as such).
class CheckpointBytes {
 public:
  CheckpointBytes(const std::filesystem::path& run_dir, const std::filesystem::path& path)
      : path_(path), in_(path, std::ios::binary) {
    if (!in_)
      throw CheckpointError(fmt::format("no checkpoint in {} ({} cannot be read)", run_dir.string(), path.string()));
    in_.seekg(0, std::ios::end);
    const auto size = static_cast<std::uint64_t>(in_.tellg());
    char magic[sizeof(kMagic)] = {};
    if (size >= sizeof(kMagic) + sizeof(stored_)) {
      read_at(0, magic, sizeof(magic));
      read_at(size - sizeof(stored_), &stored_, sizeof(stored_));
    }
    if (size < sizeof(kMagic) + sizeof(stored_) || !std::equal(kMagic, kMagic + 8, magic))
      throw CheckpointError(fmt::format("{} is not a slide checkpoint", path.string()));
    body_ = size - sizeof(stored_);
    at_ = sizeof(kMagic);
  }
  // The checksum over the whole body, read a MiB at a time.
  void verify() {
    std::vector<char> chunk(std::size_t{1} << 20);
    std::uint64_t h = kFnvStart;
    for (std::uint64_t at = 0; at < body_; at += chunk.size()) {
      const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(chunk.size(), body_ - at));
      read_at(at, chunk.data(), n);
      h = fnv1a(chunk.data(), n, h);
    }
    if (h != stored_)
      throw CheckpointError(
          fmt::format("{} is damaged (its checksum does not match: truncated or altered)", path_.string()));
  }
  template <class T>
  T get() {
    T value{};
    take(&value, sizeof(T));
    return value;
  }
  std::string get_string() {
    std::string text(checked(get<std::uint64_t>()), '\0');
    take(text.data(), text.size());
    return text;
  }
  std::uint64_t at() const { return at_; }
  std::uint64_t body() const { return body_; }
  // The bytes [from, to) of the body appended to `out`.
  void append(std::uint64_t from, std::uint64_t to, std::vector<char>& out) {
    if (from > to || to > body_) throw std::runtime_error("the state is truncated");
    const std::size_t was = out.size();
    out.resize(was + static_cast<std::size_t>(to - from));
    read_at(from, out.data() + was, static_cast<std::size_t>(to - from));
  }

 private:
  std::uint64_t checked(std::uint64_t n) const {
    if (n > body_ - at_) throw std::runtime_error("the state is truncated");
    return n;
  }
  void take(void* out, std::size_t n) {
    read_at(at_, out, checked(n));
    at_ += n;
  }
  void read_at(std::uint64_t at, void* out, std::size_t n) {
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
    if (!in_) throw CheckpointError(fmt::format("{} cannot be read", path_.string()));
  }

  std::filesystem::path path_;
  std::ifstream in_;
  std::uint64_t stored_ = 0, body_ = 0, at_ = 0;
};

CheckpointHeader read_header(CheckpointBytes& in, const std::filesystem::path& path) {
  if (const auto format = in.get<std::uint32_t>(); format != kFormat)
    throw CheckpointError(
        fmt::format("{} has checkpoint format {}, this slide reads format {}", path.string(), format, kFormat));
  CheckpointHeader h;
  h.version = in.get_string();
  h.scene_file = in.get_string();
  h.overrides.resize(in.get<std::uint64_t>());
  for (auto& o : h.overrides) o = in.get_string();
  h.resolved_scene = in.get_string();
  h.time = in.get<double>();
  h.step = in.get<long>();
  h.settling = in.get<std::uint8_t>() != 0;
  return h;
}

// A read that fails on what the file holds is a damaged file's.
template <class Read>
auto damaged_if_failed(const std::filesystem::path& path, Read&& read) {
  try {
    return read();
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw CheckpointError(fmt::format("{} is damaged: {}", path.string(), e.what()));
  }
}

}  // namespace

Checkpoint read_checkpoint(const std::filesystem::path& run_dir) { return read_checkpoint_part(run_dir, 0, 1, true); }

CheckpointHeader read_checkpoint_header(const std::filesystem::path& run_dir) {
  const auto path = checkpoint_path(run_dir);
  CheckpointBytes in(run_dir, path);
  return damaged_if_failed(path, [&] { return read_header(in, path); });
}

// The state's particle section (coupling/simulation.hpp, restore_state) begins with its head
// (fluid/particle_section_head.hpp), then the records; the part keeps the head with its own count, its records and
// all that follows them.
Checkpoint read_checkpoint_part(const std::filesystem::path& run_dir, std::uint64_t part, std::uint64_t parts,
                                bool verify) {
  if (part >= parts) throw std::invalid_argument("read_checkpoint_part: part " + std::to_string(part) + " of " +
                                                 std::to_string(parts));
  const auto path = checkpoint_path(run_dir);
  CheckpointBytes in(run_dir, path);
  if (verify) in.verify();
  return damaged_if_failed(path, [&] {
    Checkpoint c;
    c.header = read_header(in, path);
    ParticleSectionHead head = ParticleSectionHead::get(in);
    const std::uint64_t records = in.at(), record_bytes = head.record_bytes, particles = head.particles;
    if (record_bytes == 0) throw std::runtime_error("its particle section is malformed (records of 0 bytes)");
    if (particles > (in.body() - records) / record_bytes) throw std::runtime_error("the state is truncated");
    using Wide = unsigned __int128;  // (the products overflow 64 bits only for absurd counts, but need not at all)
    const auto first = static_cast<std::uint64_t>(Wide(particles) * part / parts);
    const auto end = static_cast<std::uint64_t>(Wide(particles) * (part + 1) / parts);
    head.particles = end - first;
    StateWriter part_head;
    head.put(part_head);
    c.state.assign(part_head.bytes().begin(), part_head.bytes().end());
    in.append(records + first * record_bytes, records + end * record_bytes, c.state);
    in.append(records + particles * record_bytes, in.body(), c.state);
    return c;
  });
}

}  // namespace slide::tools
