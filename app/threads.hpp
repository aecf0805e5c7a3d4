#pragma once
// --threads against the machine: more threads than cores only slows a solve down.
#include <cstdio>
#include <thread>

namespace magnus {

/// min(asked, std::thread::hardware_concurrency()) (asked when the core count is unknown), with a one-line
/// note on stderr when it is fewer than asked.
inline int usable_threads(int asked) {
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores == 0 || unsigned(asked) <= cores) return asked;
  std::fprintf(stderr, "magnus: note: --threads %d is more than the %u cores of this machine: using %u\n",
               asked, cores, cores);
  return int(cores);
}

}  // namespace magnus
