// magnus run --resume on navier-stokes cases, from checkpoints that real runs left behind (killed outright
// with SIGKILL by the test once they had checkpointed): a time.end before the checkpoint, output.snapshots,
// a changed scene, and a state that turns non-finite. Each refusal is one line, writes no result and keeps
// the checkpoint as it was. A run from rest never overwrites nor removes another scene's checkpoint.
// Coarse grids: each run takes well under a second.
#include <fmt/core.h>
#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "io/case_file.hpp"
#include "io/checkpoint.hpp"
#include "io/result_reader.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "run_child.hpp"
#include "support.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

/// Re 100, α = 1 on a coarse grid (a = 0.5 m, U = 1 m/s: the time unit D/U is 1 s), a checkpoint every
/// 2 D/U; `more` goes on in [time] (and may open further sections).
std::string resume_case(const std::string& dir, double t_end, const std::string& more = "") {
  const std::string path = dir + "/case.toml";
  std::ofstream(path) << fmt::format(
      "title = \"resume\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 1\n"
      "[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = 100\n[domain]\nouter_radius = 40.0\n[grid]\n"
      "n_theta = 48\n[time]\nend = {}\ncheckpoint_interval = 2.0\n{}",
      t_end, more);
  return path;
}

/// Run the case to dir/r.h5 and kill it outright (SIGKILL from here) once it has checkpointed a time
/// t ≥ t_min D/U: its last checkpoint, read back.
Checkpoint killed_after(const std::string& dir, const std::string& c, double t_min) {
  const test::Running run = test::start_magnus({"run", c, "-o", dir + "/r.h5"}, dir);
  test::signal_after_checkpoint(run, checkpoint_path(dir + "/r.h5"), t_min, SIGKILL);
  const test::Ended e = test::wait_magnus(run);
  REQUIRE_FALSE(e.exited);
  REQUIRE(e.status == SIGKILL);
  REQUIRE_FALSE(fs::exists(dir + "/r.h5"));
  const Checkpoint cp = read_checkpoint(checkpoint_path(dir + "/r.h5"), load_case(c, {}));
  REQUIRE(cp.state.t >= t_min);
  return cp;
}

/// magnus run CASE -o dir/r.h5 --resume with the --set overrides.
test::Outcome resume(const std::string& dir, const std::string& c, const std::vector<std::string>& sets) {
  std::vector<std::string> args = {"run", c, "-o", dir + "/r.h5", "--resume"};
  for (const std::string& s : sets) args.push_back("--set"), args.push_back(s);
  return test::magnus_cmd(args, dir);
}

/// A refusal: non-zero status, one line holding `text`, no result, the checkpoint byte for byte as before.
void require_refused(const test::Outcome& o, const std::string& text, const std::string& dir,
                     const std::string& checkpoint_bytes) {
  INFO(o.err);
  REQUIRE(o.status != 0);
  REQUIRE(test::lines(o.err) == 1);
  REQUIRE(o.err.find(text) != std::string::npos);
  REQUIRE(o.out.empty());
  REQUIRE_FALSE(fs::exists(dir + "/r.h5"));
  REQUIRE_FALSE(fs::exists(dir + "/r.xmf"));
  REQUIRE(test::slurp(checkpoint_path(dir + "/r.h5")) == checkpoint_bytes);
}

}  // namespace

TEST_CASE("navier-stokes --resume: a time.end before the checkpoint's time is refused, the checkpoint kept",
          "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-end");
  const std::string c = resume_case(dir, 12);
  const Checkpoint cp = killed_after(dir, c, 4);
  const std::string ckpt = checkpoint_path(dir + "/r.h5"), bytes = test::slurp(ckpt);
  require_refused(resume(dir, c, {"time.end=2"}),
                  fmt::format("time.end = 2 D/U is before the checkpoint's time t = {:.6g} D/U", cp.state.t),
                  dir, bytes);
}

TEST_CASE("navier-stokes --resume: time.end at the checkpoint's time takes no step, and the summary says so",
          "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-same-end");
  const std::string c = resume_case(dir, 12);
  const Checkpoint cp = killed_after(dir, c, 4);
  REQUIRE(cp.steps > 100);  // from rest: Δt ≈ 0.03 D/U
  const std::string ckpt = checkpoint_path(dir + "/r.h5");
  // The run line is the marched run's (t, 0 steps), not the one of a steady state by Newton's method.
  const auto o = resume(dir, c, {fmt::format("time.end={}", cp.state.t)});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("Newton") == std::string::npos);
  // The steps count from rest: those before the checkpoint, none of them this run's.
  CHECK(o.out.find(fmt::format(" {} steps ({} before --resume) of Δt", cp.steps, cp.steps)) !=
        std::string::npos);
  CHECK(o.out.find("stopped: reached t_end") != std::string::npos);
  const FlowResult r = read_result(dir + "/r.h5");
  CHECK(r.viscous->t == cp.state.t);
  CHECK(r.viscous->steps == cp.steps);
  CHECK_FALSE(fs::exists(ckpt));
}

TEST_CASE("navier-stokes --resume: a checkpoint of another scene is refused naming what differs, and kept",
          "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-scene");
  const std::string c = resume_case(dir, 12);
  const Checkpoint cp = killed_after(dir, c, 2);
  REQUIRE(cp.state.t < 12.0);
  const std::string ckpt = checkpoint_path(dir + "/r.h5"), bytes = test::slurp(ckpt);
  const std::string where = "checkpoint '" + ckpt + "' is from another scene: ";
  require_refused(
      resume(dir, c, {"flow.reynolds=80"}),
      where +
          "flow.viscosity 0.01 there, 0.0125 here; flow.reynolds 100 there, 80 here; remove it or run "
          "without --resume",
      dir, bytes);
  require_refused(resume(dir, c, {"solver.advection_order=4"}),
                  where + "solver.advection_order 2 there, 4 here; remove it or run without --resume", dir,
                  bytes);
  require_refused(resume(dir, c, {"grid.n_theta=32"}), where + "grid.n_theta 48 there, 32 here", dir, bytes);
  // The kept checkpoint still serves its own scene.
  const auto o = resume(dir, c, {});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(read_result(dir + "/r.h5").viscous->t == Approx(12.0));
  CHECK_FALSE(fs::exists(ckpt));
}

TEST_CASE("navier-stokes --resume: output.snapshots trims the checkpoint's snapshots to the newest ones",
          "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-snap");
  const std::string c = resume_case(dir, 12, "[output]\nsnapshots = 20\nsnapshot_interval = 0.05\n");
  const Checkpoint cp = killed_after(dir, c, 2);
  REQUIRE(cp.snapshots.size() == 20);
  const std::string ckpt = checkpoint_path(dir + "/r.h5");
  fs::copy_file(ckpt, dir + "/saved.h5");
  // None kept: the result holds no snapshot.
  const double t_end = cp.state.t + 0.12;
  auto o = resume(dir, c, {"output.snapshots=0", fmt::format("time.end={}", t_end)});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(read_result(dir + "/r.h5").viscous->snapshots.empty());
  // Five kept: the newest five, the checkpoint's last ones first, then those of the resumed run.
  fs::copy_file(dir + "/saved.h5", ckpt, fs::copy_options::overwrite_existing);
  o = resume(dir, c, {"output.snapshots=5", fmt::format("time.end={}", t_end)});
  INFO(o.err);
  REQUIRE(o.status == 0);
  const std::vector<Snapshot> s = read_result(dir + "/r.h5").viscous->snapshots;
  REQUIRE(s.size() == 5);
  size_t old = 0;  // those from the checkpoint
  while (old < s.size() && s[old].t <= cp.state.t) ++old;
  REQUIRE(old >= 1);
  REQUIRE(old < 5);
  for (size_t k = 0; k < old; ++k) {
    const Snapshot& want = cp.snapshots[cp.snapshots.size() - old + k];
    CHECK(s[k].t == want.t);
    CHECK(s[k].vorticity == want.vorticity);
  }
  for (size_t k = 1; k < s.size(); ++k) CHECK(s[k].t > s[k - 1].t);
  CHECK(s.back().t <= t_end);
}

TEST_CASE("navier-stokes --resume: a state that turns non-finite stops in one line, the checkpoint kept",
          "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-blowup");
  const std::string c = resume_case(dir, 12);
  Checkpoint cp = killed_after(dir, c, 2);
  REQUIRE(cp.state.t < 12.0);
  // A huge but finite vorticity in the middle of the grid (away from the wall, where the forces are taken):
  // the checkpoint reads, and the first step's right-hand side overflows (1e300 would not: the step would
  // go through and the next one stop on its CFL number instead).
  const Case cs = load_case(c, {});
  const PolarGrid g = ns_grid(ns_params(cs));
  cp.state.zeta[size_t(g.n_r / 2) * size_t(g.n_theta) + 3] = 1e308;
  const std::string ckpt = checkpoint_path(dir + "/r.h5");
  write_checkpoint(ckpt, cs, cp);
  const std::string bytes = test::slurp(ckpt);
  const auto o = resume(dir, c, {});
  require_refused(o, "the flow turned non-finite at t = ", dir, bytes);
  CHECK(o.err.find("likely cause") != std::string::npos);
  // The time named is the failing step's: the checkpoint's plus one step (Δt < 0.1 D/U = 0.1 s).
  const size_t at = o.err.find("at t = ") + 7;
  const double t_fail = std::stod(o.err.substr(at));
  CHECK(t_fail > cp.state.t);
  CHECK(t_fail < cp.state.t + 0.1);
  for (const char* bad : {"nan", "inf"}) CHECK(o.err.find(bad) == std::string::npos);
}

TEST_CASE(
    "navier-stokes run from rest: another scene's checkpoint is refused and kept, its own stays unless "
    "it wrote it",
    "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-foreign");
  const std::string c = resume_case(dir, 12);
  const Checkpoint cp = killed_after(dir, c, 2);
  REQUIRE(cp.state.t < 12.0);
  const std::string ckpt = checkpoint_path(dir + "/r.h5"), bytes = test::slurp(ckpt);
  // Another scene to the same output without --resume: refused before solving, naming whose it is.
  require_refused(
      test::magnus_cmd({"run", c, "-o", dir + "/r.h5", "--set", "flow.reynolds=80"}, dir),
      "magnus: error: checkpoint '" + ckpt +
          "' is from another scene: flow.viscosity 0.01 there, 0.0125 here; flow.reynolds 100 there, "
          "80 here; a run from rest would overwrite it: resume that scene (--resume), remove it, or "
          "give another -o\n",
      dir, bytes);
  // The same scene from rest, ending before it writes a checkpoint of its own: complete, and the checkpoint
  // it did not write stays, byte for byte.
  const auto fresh = test::magnus_cmd({"run", c, "-o", dir + "/r.h5", "--set", "time.end=1", "-q"}, dir);
  INFO(fresh.err);
  REQUIRE(fresh.status == 0);
  REQUIRE(read_result(dir + "/r.h5").viscous->t == Approx(1.0));
  REQUIRE(test::slurp(ckpt) == bytes);
  // ...and still goes on from where the killed run stopped.
  const auto o = resume(dir, c, {});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(read_result(dir + "/r.h5").viscous->t == Approx(12.0));
  CHECK_FALSE(fs::exists(ckpt));
}

TEST_CASE("navier-stokes: a failure during the march is the error alone, not why the run marched",
          "[app][ns][resume]") {
  const std::string dir = test::temp_dir("ns-resume-error");
  const Case c = load_case(resume_case(dir, 3), {});  // time.mode "auto" at Re 100: it marches at once
  ViscousHooks hooks;
  hooks.on_checkpoint = [](const Checkpoint&) {
    throw std::runtime_error("cannot write 'r.checkpoint.h5': No space left on device");
  };
  CHECK_THROWS_WITH(run_viscous(c, hooks), "cannot write 'r.checkpoint.h5': No space left on device");
}
