// A snapshot chunk encoded as HDF5 stores it (tools/snapshot_chunk.hpp): HDF5's byte shuffle, the zero padding of a
// dataset's last chunk, and zlib's stream that inflates back to them.
#include <gtest/gtest.h>
#include <zlib.h>

#include <numeric>
#include <vector>

#include "tools/snapshot_chunk.hpp"

using slide::tools::encoded_chunk;
using slide::tools::shuffled;

TEST(SnapshotChunk, ShuffleGathersEachByteOfTheElements) {
  const std::vector<unsigned char> bytes{0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23, 99};
  // Three elements of four bytes: byte 0 of each, then byte 1 of each, ...; the byte past them stays last.
  EXPECT_EQ(shuffled(bytes, 4), (std::vector<unsigned char>{0, 10, 20, 1, 11, 21, 2, 12, 22, 3, 13, 23, 99}));
  EXPECT_EQ(shuffled(bytes, 1), bytes);
  // Padded with zeros to 20 bytes: five elements, the fourth given in part (byte 12), the fifth not at all.
  EXPECT_EQ(shuffled(bytes, 4, 20), (std::vector<unsigned char>{0, 10, 20, 99, 0, 1, 11, 21, 0, 0, 2, 12, 22, 0, 0, 3,
                                                                13, 23, 0, 0}));
  std::vector<unsigned char> padded = bytes;
  padded.resize(20, 0);
  EXPECT_EQ(shuffled(bytes, 4, 20), shuffled(padded, 4));
}

TEST(SnapshotChunk, AChunkIsItsRowsPaddedWithZerosAndDeflatesBackToThem) {
  std::vector<unsigned char> rows(24);
  std::iota(rows.begin(), rows.end(), 1);
  std::vector<unsigned char> padded = rows;
  padded.resize(40, 0);
  EXPECT_EQ(encoded_chunk(rows, 40, 8, false), padded);
  const std::vector<unsigned char> deflated = encoded_chunk(rows, 40, 8, true);
  std::vector<unsigned char> inflated(40);
  uLongf size = inflated.size();
  ASSERT_EQ(uncompress(inflated.data(), &size, deflated.data(), deflated.size()), Z_OK);
  EXPECT_EQ(size, 40u);
  EXPECT_EQ(inflated, shuffled(padded, 8));
}
