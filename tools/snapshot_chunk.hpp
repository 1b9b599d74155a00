#pragma once
// One chunk of a snapshot's dataset, encoded as HDF5 stores it, so that the process holding its rows encodes it and the
// first process writes it as it is (H5Dwrite_chunk, tools/snapshot_writer.cpp): a snapshot's compression is spread over
// the processes, and the file's bytes do not depend on which process encoded which chunk.
#include <cstddef>
#include <span>
#include <vector>

namespace slide::tools {

// HDF5's shuffle filter (H5Zshuffle.c) of `bytes` padded with zeros to `size` bytes (at least bytes.size()): byte k of
// every element, for k = 0 .. element_bytes - 1, one after another (bytes past the last whole element stay at the end).
std::vector<unsigned char> shuffled(std::span<const unsigned char> bytes, std::size_t element_bytes,
                                    std::size_t size = 0);

// A chunk as the file holds it: `rows` (the chunk's rows, fewer than chunk_bytes only in a dataset's last chunk) padded
// with zeros to chunk_bytes (HDF5's default fill value), then, deflated, shuffled and compressed by zlib at level 1 as
// HDF5's deflate filter does (compress2, H5Zdeflate.c). Throws std::runtime_error where zlib fails.
std::vector<unsigned char> encoded_chunk(std::span<const unsigned char> rows, std::size_t chunk_bytes,
                                         std::size_t element_bytes, bool deflate);

}  // namespace slide::tools
