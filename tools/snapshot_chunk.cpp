#include "tools/snapshot_chunk.hpp"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace slide::tools {

std::vector<unsigned char> shuffled(std::span<const unsigned char> bytes, std::size_t element_bytes, std::size_t size) {
  size = std::max(size, bytes.size());
  std::vector<unsigned char> out(size, 0);
  const std::size_t elements = element_bytes == 0 ? 0 : size / element_bytes;
  if (elements <= 1) {
    std::copy(bytes.begin(), bytes.end(), out.begin());
    return out;
  }
  const std::size_t given = bytes.size() / element_bytes;  // whole elements given; the rest of them are zeros
  for (std::size_t k = 0; k < element_bytes; ++k)
    for (std::size_t e = 0; e < given; ++e) out[k * elements + e] = bytes[e * element_bytes + k];
  for (std::size_t b = elements * element_bytes; b < bytes.size(); ++b) out[b] = bytes[b];  // past whole elements
  for (std::size_t b = given * element_bytes; b < std::min(bytes.size(), elements * element_bytes); ++b)
    out[(b % element_bytes) * elements + b / element_bytes] = bytes[b];  // a last element given in part
  return out;
}

std::vector<unsigned char> encoded_chunk(std::span<const unsigned char> rows, std::size_t chunk_bytes,
                                         std::size_t element_bytes, bool deflate) {
  if (!deflate) {
    std::vector<unsigned char> padded(std::max(chunk_bytes, rows.size()), 0);
    std::copy(rows.begin(), rows.end(), padded.begin());
    return padded;
  }
  const std::vector<unsigned char> plain = shuffled(rows, element_bytes, chunk_bytes);
  uLongf size = compressBound(static_cast<uLong>(plain.size()));
  std::vector<unsigned char> out(size);
  const int rc = compress2(out.data(), &size, plain.data(), static_cast<uLong>(plain.size()), 1);
  if (rc != Z_OK)
    throw std::runtime_error("zlib could not compress a snapshot chunk (error " + std::to_string(rc) + ")");
  out.resize(size);
  return out;
}

}  // namespace slide::tools
