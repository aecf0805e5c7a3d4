// for_each_index (solver/work_queue.hpp): every index once, on any number of threads, and a task's
// exception handed to the caller only after every thread has finished.
#include <catch2/catch.hpp>
#include <atomic>
#include <stdexcept>
#include <vector>

#include "solver/work_queue.hpp"

using namespace magnus;

TEST_CASE("[work_queue] every index runs once, and a task's exception reaches the caller", "[work_queue]") {
  for (size_t threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> runs(17);
    for_each_index(runs.size(), threads, [&](size_t i) { ++runs[i]; });
    for (const auto& r : runs) CHECK(r == 1);
  }
  std::atomic<int> finished{0};
  CHECK_THROWS_WITH(for_each_index(8, 2,
                                   [&](size_t i) {
                                     if (i == 3) throw std::runtime_error("task 3 failed");
                                     ++finished;
                                   }),
                    "task 3 failed");
  // The thread that threw stops taking indices; the other finishes all the rest before the rethrow.
  CHECK(finished == 7);
  for_each_index(0, 2, [](size_t) { throw std::logic_error("no task runs when n = 0"); });
}
