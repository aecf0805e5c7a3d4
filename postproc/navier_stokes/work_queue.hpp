#pragma once
// Independent tasks on the cores: each thread takes the next index as it comes free.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

namespace magnus {

/// task(i) for i = 0 … n − 1, each once, on min(threads, n) threads at once (the caller's among them),
/// the indices taken in increasing order as threads come free; returns when every task is done. task
/// must not throw (catch inside it: each caller reports a failed task its own way).
inline void for_each_index(size_t n, size_t threads, const std::function<void(size_t)>& task) {
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i; (i = next++) < n;) task(i);
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < std::min(threads, n); ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

}  // namespace magnus
