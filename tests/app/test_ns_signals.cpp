// The life of a navier-stokes `magnus run` around its output: SIGTERM (as schedulers send it) writes the
// partial result and the checkpoint and exits 143; a second run to the same output or checkpoint is
// refused while the first holds them; a checkpoint that cannot be written is a warning and the run goes
// on; the free-space check counts the result and the checkpoint on the grid as built. The faults come from
// this side (signals, a directory moved away), never from the program.
#include <fmt/core.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

#include "app/run_viscous.hpp"
#include "io/case_file.hpp"
#include "io/checkpoint.hpp"
#include "io/output_size.hpp"
#include "io/result_reader.hpp"
#include "run_child.hpp"
#include "solver/memory.hpp"
#include "support.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

/// Re 100, α = 1 on a coarse grid (a = 0.5 m, U = 1 m/s: D/U = 1 s), time.mode "unsteady" to time.end
/// (a run that goes on until it is stopped when t_end is large), a checkpoint every D/U; `more` opens
/// further sections.
std::string signal_case(const std::string& dir, double t_end, const std::string& more = "") {
  const std::string path = dir + "/case.toml";
  std::ofstream(path) << fmt::format(
      "title = \"signals\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 1\n"
      "[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = 100\n[domain]\nouter_radius = 40.0\n[grid]\n"
      "n_theta = 48\n[time]\nmode = \"unsteady\"\nmean_tolerance = 1e-12\nend = {}\ncheckpoint_interval = "
      "1.0\n"
      "{}",
      t_end, more);
  return path;
}

}  // namespace

TEST_CASE(
    "navier-stokes run: SIGTERM writes the partial result and checkpoint and exits 143, the output is "
    "locked while it runs",
    "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-term");
  const std::string c = signal_case(dir, 100000), out = dir + "/r.h5", ckpt = checkpoint_path(out);
  const test::Running first = test::start_magnus({"run", c, "-o", out}, dir, "first");
  test::signal_after_checkpoint(first, ckpt, 1.0, 0);  // signal 0: only wait until it is stepping
  const std::string pid = std::to_string(first.pid);
  // A second run to the same output: refused in one line naming the first, before it writes anything
  // (unlocked, it would end at once: time.end = 0.5 D/U).
  const auto second =
      test::magnus_cmd({"run", c, "-o", out, "--set", "output.snapshots=3", "--set", "time.end=0.5"}, dir);
  CHECK(second.status == 1);
  CHECK(second.err == "magnus: error: cannot write '" + out + "': another magnus run (PID " + pid +
                          ") is writing it (lock file '" + out +
                          ".lock'); wait for it to end or give another -o\n");
  // Another output with the same checkpoint (r.hdf → r.checkpoint.h5): refused too.
  const auto third = test::magnus_cmd({"run", c, "-o", dir + "/r.hdf", "--set", "time.end=0.5"}, dir);
  CHECK(third.status == 1);
  CHECK(third.err.find("cannot write '" + ckpt + "': another magnus run (PID " + pid + ")") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(dir + "/r.hdf"));

  REQUIRE(::kill(first.pid, SIGTERM) == 0);
  const test::Ended e = test::wait_magnus(first);
  INFO(e.err);
  REQUIRE(e.exited);
  CHECK(e.status == 128 + SIGTERM);
  const FlowResult part = read_result(out);
  REQUIRE(part.viscous->partial);
  CHECK(part.viscous->status.find("interrupted") != std::string::npos);
  // The checkpoint holds the state the partial result ends on: --resume loses nothing.
  const Checkpoint cp = read_checkpoint(ckpt, load_case(c, {}));
  CHECK(cp.state.t == part.viscous->t);
  CHECK(cp.steps == part.viscous->steps);
  const std::string go_on = "magnus run " + c + " -o " + out + " --resume";
  CHECK(e.out.find("checkpoint     " + ckpt + " — go on with: " + go_on + "\n") != std::string::npos);
  CHECK(e.err.find("magnus: interrupted by SIGTERM at t = ") != std::string::npos);
  CHECK(e.err.find(go_on) != std::string::npos);
  CHECK_FALSE(fs::exists(out + ".lock"));  // released and removed
  CHECK_FALSE(fs::exists(ckpt + ".lock"));
  // Resumed to a near end: complete, the total of the steps counted from rest.
  const auto done = test::magnus_cmd(
      {"run", c, "-o", out, "--resume", "--set", fmt::format("time.end={}", cp.state.t + 0.5), "-q"}, dir);
  INFO(done.err);
  REQUIRE(done.status == 0);
  const FlowResult r = read_result(out);
  CHECK_FALSE(r.viscous->partial);
  CHECK(r.viscous->steps > cp.steps);
  CHECK(r.viscous->steps < cp.steps + 40);  // 0.5 D/U at Δt ≈ 0.03 D/U
  CHECK_FALSE(fs::exists(ckpt));
}

TEST_CASE("navier-stokes run: a lock that a killed run left behind does not block the next run",
          "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-stale-lock");
  const std::string c = signal_case(dir, 2), out = dir + "/r.h5";
  std::ofstream(out + ".lock") << "999999999\n";  // the file of a run that is gone: no lock held on it
  const auto o = test::magnus_cmd({"run", c, "-o", out, "-q"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(read_result(out).viscous->t == Approx(2.0));
  CHECK_FALSE(fs::exists(out + ".lock"));
}

TEST_CASE("navier-stokes run: a checkpoint that cannot be written is a warning, the run goes on",
          "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-ckpt-fail");
  const std::string c = signal_case(dir, 100000), out = dir + "/r.h5", ckpt = checkpoint_path(out);
  // The checkpoint is a link into a directory that this test moves away once the run has checkpointed there:
  // every later checkpoint fails (as on a full disk), the result beside it does not.
  fs::create_directory(dir + "/elsewhere");
  fs::create_symlink(dir + "/elsewhere/c.h5", ckpt);
  const test::Running run = test::start_magnus({"run", c, "-o", out}, dir);
  test::signal_after_checkpoint(run, dir + "/elsewhere/c.h5", 1.0, 0);
  fs::rename(dir + "/elsewhere", dir + "/gone");  // at once, even while the run writes in it
  // Stepping on past at least one failed checkpoint (every D/U) before it is stopped.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  REQUIRE(::kill(run.pid, SIGTERM) == 0);
  const test::Ended e = test::wait_magnus(run);
  INFO(e.err);
  REQUIRE(e.exited);
  CHECK(e.status == 128 + SIGTERM);
  CHECK(e.err.find("magnus: warning: no checkpoint at t = ") != std::string::npos);
  CHECK(e.err.find("(cannot write '" + ckpt + "': ") != std::string::npos);
  CHECK(e.err.find("); the run goes on, the previous checkpoint stays\n") != std::string::npos);
  // A warning for each new reason (a write under way when the directory went, then a missing directory),
  // not one at every checkpoint; then the interruption.
  CHECK(test::lines(e.err) >= 2);
  CHECK(test::lines(e.err) <= 3);
  const FlowResult part = read_result(out);
  CHECK(part.viscous->partial);
  CHECK(part.viscous->t > 2.0);  // it went on past the first failure
}

TEST_CASE("the free-space estimate of a navier-stokes run covers its result and checkpoint",
          "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-space");
  const std::string c = signal_case(dir, 6, "[output]\nsnapshots = 30\nsnapshot_interval = 0.1\n");
  const std::string out = dir + "/r.h5", ckpt = checkpoint_path(out);
  // The checkpoint at its largest (all 30 snapshots kept), then the result of the same run.
  const test::Running run = test::start_magnus({"run", c, "-o", out}, dir);
  test::signal_after_checkpoint(run, ckpt, 4.0, SIGKILL);
  test::wait_magnus(run);
  const uintmax_t checkpoint_bytes = fs::file_size(ckpt);
  const auto o = test::magnus_cmd({"run", c, "-o", out, "-q", "--resume"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const uintmax_t result_bytes = fs::file_size(out);
  // On the grid as built (n_r = 48 here: square cells to R = 40a, not the potential flow's ring count), both
  // files, and not far above them (the history is bounded by the start's Δt, the smallest of the run).
  const size_t estimate = estimated_run_bytes(load_case(c, {}));
  CAPTURE(checkpoint_bytes, result_bytes, estimate);
  CHECK(estimate >= checkpoint_bytes + result_bytes);
  CHECK(double(estimate) < 1.3 * double(checkpoint_bytes + result_bytes));
}

TEST_CASE("a navier-stokes run whose result and checkpoint need more than the free space is refused at once",
          "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-full");
  // 10000 snapshots on a fine grid: hundreds of GB (the estimate is checked against the free space first).
  const std::string c = signal_case(dir, 2, "[output]\nsnapshots = 10000\n");
  const std::vector<std::string> sets = {"grid.n_theta=2048"};
  const size_t need = estimated_run_bytes(load_case(c, sets));
  const std::optional<size_t> free_bytes = free_bytes_for(dir + "/r.h5");
  REQUIRE(free_bytes);
  if (*free_bytes >= need) {
    WARN("skipped: " << *free_bytes << " bytes free, more than the " << need << " this run needs");
    return;
  }
  const auto o = test::magnus_cmd({"run", c, "-o", dir + "/r.h5", "--set", sets[0]}, dir);
  CHECK(o.status == 1);
  // The grid's memory is checked first (the snapshots are held in memory too): on a machine with more disk
  // than memory that refusal comes first, naming the grid; else the disk's, naming the file.
  const bool memory = o.err.find("with its companion run, more than the memory available") != std::string::npos;
  if (memory)
    CHECK(o.err.rfind("magnus: error: grid.n_theta: the grid needs n_θ 2048", 0) == 0);
  else
    CHECK(o.err.rfind(
              "magnus: error: " + dir + "/r.h5: the result and its checkpoint need about " + format_bytes(need),
              0) == 0);
  CHECK(test::lines(o.err) == 1);
  CHECK_FALSE(fs::exists(dir + "/r.h5"));
  CHECK_FALSE(fs::exists(checkpoint_path(dir + "/r.h5")));
}

TEST_CASE("navier-stokes run: concurrent runs to one output leave a result and .xmf of the same run",
          "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-concurrent");
  const std::string c = signal_case(dir, 3.2, "[output]\nsnapshot_interval = 0.1\n"), out = dir + "/r.h5";
  for (int trial = 0; trial < 3; ++trial) {
    // Four runs at once, each keeping another number of snapshots (4 … 7): each completes, or is refused
    // in one line because another holds the output.
    std::vector<test::Running> runs;
    for (int k = 0; k < 4; ++k)
      runs.push_back(
          test::start_magnus({"run", c, "-o", out, "-q", "--set", fmt::format("output.snapshots={}", 4 + k)},
                             dir, fmt::format("run{}", k)));
    int done = 0;
    for (const test::Running& r : runs) {
      const test::Ended e = test::wait_magnus(r);
      INFO(e.err);
      REQUIRE(e.exited);
      if (e.status == 0) {
        ++done;
        continue;
      }
      CHECK(e.status == 1);
      CHECK(test::lines(e.err) == 1);
      CHECK(e.err.find("another magnus run (PID ") != std::string::npos);
    }
    REQUIRE(done >= 1);
    // The sidecar lists exactly the snapshots the file holds.
    const std::string xmf = test::slurp(dir + "/r.xmf");
    size_t times = 0;
    for (size_t at = xmf.find("<Time "); at != std::string::npos; at = xmf.find("<Time ", at + 1)) ++times;
    CHECK(times == read_result(out).viscous->snapshots.size());
  }
}

TEST_CASE("navier-stokes run: SIGKILL while a checkpoint is written leaves the previous one byte for byte",
          "[app][ns][signals]") {
  const std::string dir = test::temp_dir("ns-signals-kill-ckpt");
  // n_θ = 192 and 100 snapshots: a checkpoint of about 35 MB, long enough to be caught while written.
  // time.end 10^4 D/U: the march is stopped long before, and stays below the 10^7 steps a run may take.
  const std::string c = signal_case(dir, 10000, "[output]\nsnapshots = 100\nsnapshot_interval = 0.01\n");
  const std::string out = dir + "/r.h5", ckpt = checkpoint_path(out);
  int killed_mid_write = 0;
  for (int trial = 0; trial < 3; ++trial) {
    const test::Running run = test::start_magnus({"run", c, "-o", out, "--set", "grid.n_theta=192"}, dir);
    test::signal_after_checkpoint(run, ckpt, 0.0, 0);
    const std::string before = test::slurp(ckpt);
    const double t_before = test::checkpoint_time(ckpt);
    // The next checkpoint's temporary, once 1 MB of it is written.
    const std::string tmp = dir + "/.r.checkpoint.h5.tmp-" + std::to_string(run.pid);
    bool seen = false;
    for (int k = 0; k < 120000 && !seen; ++k) {
      std::error_code ec;
      seen = fs::file_size(tmp, ec) >= (uintmax_t(1) << 20) && !ec;
      if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    REQUIRE(seen);
    REQUIRE(::kill(run.pid, SIGKILL) == 0);
    const test::Ended e = test::wait_magnus(run);
    REQUIRE_FALSE(e.exited);
    REQUIRE_FALSE(fs::exists(out));
    if (test::slurp(ckpt) == before) {
      ++killed_mid_write;
    } else {
      // It finished between the look and the kill: then the new checkpoint is complete, and later.
      REQUIRE(test::checkpoint_time(ckpt) > t_before);
    }
    fs::remove(ckpt);  // the next trial from rest
  }
  CHECK(killed_mid_write >= 2);
}
