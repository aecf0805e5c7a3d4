#pragma once
// The machine's sustained memory bandwidth, measured once (magnus bench prints the bound it sets on a step).
#include <cstddef>

namespace magnus {

/// The last-level cache (the largest the system reports), bytes; 0 when it does not say.
std::size_t last_level_cache_bytes();

/// Sustained bandwidth, bytes/s: the best of `repeats` passes of the STREAM triad a_i = b_i + s·c_i over three
/// arrays of `bytes_each` bytes, split over `threads` threads. 24 bytes counted per element (two reads, one
/// write, as STREAM counts them; the write's read-for-ownership is not counted). bytes_each = 0: the larger
/// of 64 MiB and the last-level cache, so the three arrays never fit in the caches.
double triad_bandwidth(int threads = 1, std::size_t bytes_each = 0, int repeats = 4);

}  // namespace magnus
