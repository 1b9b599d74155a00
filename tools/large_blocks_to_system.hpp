#pragma once
// glibc's allocator policy for slide's large arrays, set once at the start of main.
#include <malloc.h>

#include <cstdlib>

namespace slide::tools {

// Every block of 128 kB or more in pages of its own, which go back to the system when the block is freed.
// Why: glibc raises its mmap threshold each time such a block is freed (up to 32 MB), and from then on serves blocks
// of that size from its heap, which does not shrink: the arrays a neighbour-list rebuild or a migration frees and
// makes again then stay resident. Measured at stop 60 on the 3-D bench run to its end on one process (the same with
// MALLOC_MMAP_THRESHOLD_=131072, which this sets): the peak 322.3 MB against 362.4 MB, against 284.7 MB after its
// first steps. The cost measured: docs/using.md (memory). Setting the threshold turns glibc's raising off. A
// MALLOC_MMAP_THRESHOLD_ in the environment is left to rule (a user's own tuning).
inline void large_blocks_to_system() {
  if (!std::getenv("MALLOC_MMAP_THRESHOLD_")) mallopt(M_MMAP_THRESHOLD, 128 * 1024);
}

}  // namespace slide::tools
