#include "tools/snapshot_chunk.hpp"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace slide::tools {

std::vector<unsigned char> shuffled(std::span<const unsigned char> bytes, std::size_t element_bytes) {
  std::vector<unsigned char> out(bytes.begin(), bytes.end());
  const std::size_t elements = element_bytes == 0 ? 0 : bytes.size() / element_bytes;
  for (std::size_t k = 0; k < element_bytes && elements > 1; ++k)
    for (std::size_t e = 0; e < elements; ++e) out[k * elements + e] = bytes[e * element_bytes + k];
  return out;
}

std::vector<unsigned char> encoded_chunk(std::span<const unsigned char> rows, std::size_t chunk_bytes,
                                         std::size_t element_bytes, bool deflate) {
  std::vector<unsigned char> padded(std::max(chunk_bytes, rows.size()), 0);
  std::copy(rows.begin(), rows.end(), padded.begin());
  if (!deflate) return padded;
  const std::vector<unsigned char> plain = shuffled(padded, element_bytes);
  uLongf size = compressBound(static_cast<uLong>(plain.size()));
  std::vector<unsigned char> out(size);
  const int rc = compress2(out.data(), &size, plain.data(), static_cast<uLong>(plain.size()), 1);
  if (rc != Z_OK)
    throw std::runtime_error("zlib could not compress a snapshot chunk (error " + std::to_string(rc) + ")");
  out.resize(size);
  return out;
}

}  // namespace slide::tools
