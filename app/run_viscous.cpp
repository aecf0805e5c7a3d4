#include "app/run_viscous.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

#include "io/checkpoint.hpp"
#include "io/hdf5_io.hpp"
#include "io/report.hpp"

namespace magnus {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_sigint(int) {
  g_interrupted = 1;
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the program at once
}

/// Before the march: Ctrl-C ends the program at once, as by default (also where the shell started it with
/// SIGINT ignored, as it does for a background job).
extern "C" void on_sigint_now(int) {
  std::signal(SIGINT, SIG_DFL);
  std::raise(SIGINT);
}

/// Ctrl-C stops the run at the next step (a partial result is written) while this lives.
struct InterruptGuard {
  InterruptGuard() {
    g_interrupted = 0;
    previous = std::signal(SIGINT, on_sigint);
  }
  ~InterruptGuard() { std::signal(SIGINT, previous); }
  void (*previous)(int) = SIG_DFL;
};

std::string clock_text(double seconds) {
  const long s = long(seconds + 0.5);
  return s >= 3600 ? fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60)
                   : fmt::format("{}:{:02d}", s / 60, s % 60);
}

}  // namespace

FlowResult run_viscous_case(const Case& c, bool resume, bool quiet, int threads) {
  const std::string ckpt = checkpoint_path(c.output.file);
  std::unique_ptr<Checkpoint> start;
  if (resume) start = std::make_unique<Checkpoint>(read_checkpoint(ckpt, c));

  const double unit = 2.0 * c.scene.radius / c.scene.reference_speed();
  const double t_end = c.time.end * unit;
  const bool progress = !quiet && isatty(STDERR_FILENO);
  const auto clock0 = std::chrono::steady_clock::now();
  auto last_print = clock0;
  const double t0 = start ? start->state.t : 0.0;
  long steps = 0;
  bool printed = false;
  // For the tests of --resume: kill the process outright (no clean-up) once t reaches this, in D/U.
  const char* kill_at = std::getenv("MAGNUS_TEST_KILL_AT");
  const double t_kill = kill_at ? std::atof(kill_at) * unit : -1.0;

  // Ctrl-C stops the march at the next step with a partial result; before the march (the Newton solve and
  // stability test of time.mode "steady" or "auto") nothing is computed yet that a result could keep, so
  // there Ctrl-C ends the program at once: the handler is installed with the first step.
  std::optional<InterruptGuard> guard;
  ViscousHooks hooks;
  hooks.on_step = [&](const NsState& s, const ViscousForces& f) {
    if (!guard) guard.emplace();
    ++steps;
    if (t_kill >= 0.0 && s.t >= t_kill) std::raise(SIGKILL);
    if (progress) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_print > std::chrono::milliseconds(250)) {
        last_print = now;
        const double el = std::chrono::duration<double>(now - clock0).count();
        const double rate = el > 0.0 ? (s.t - t0) / el : 0.0;  // simulated s per wall s
        const std::string coeffs = f.C_L ? fmt::format("C_L = {:+.4f}  C_D = {:.4f}", *f.C_L, *f.C_D)
                                         : fmt::format("M = {:+.4g} N·m/m", f.M);
        std::fprintf(stderr, "\r\033[K  t = %.1f %s of %.0f  %s  %.0f steps/s  ETA ≤ %s   ", s.t / unit,
                     time_unit_name(c.scene), c.time.end, coeffs.c_str(), double(steps) / std::max(el, 1e-9),
                     rate > 0.0 ? clock_text((t_end - s.t) / rate).c_str() : "?");
        std::fflush(stderr);
        printed = true;
      }
    }
    return g_interrupted == 0;
  };
  hooks.on_checkpoint = [&](const Checkpoint& cp) { write_checkpoint(ckpt, c, cp); };

  if (progress && !start && c.time.mode != TimeMode::unsteady) {
    std::fputs(c.time.mode == TimeMode::steady
                   ? "  solving the steady equations by Newton's method (Ctrl-C stops) …"
                   : "  auto: looking for a stable steady state (Newton's method, eigenvalues; Ctrl-C stops) …",
               stderr);
    std::fflush(stderr);
    printed = true;
  }
  FlowResult r;
  void (*before_march)(int) = std::signal(SIGINT, on_sigint_now);
  try {
    r = run_viscous(c, hooks, start.get(), threads);
  } catch (...) {
    guard.reset();
    std::signal(SIGINT, before_march);
    if (printed) std::fputs("\n", stderr);
    throw;
  }
  guard.reset();
  std::signal(SIGINT, before_march);
  if (printed) std::fputs("\n", stderr);
  write_result(r, c.output.file, c.output.compression);
  // Complete: the checkpoint has served. Interrupted: run_viscous checkpointed the last state, so
  // --resume goes on from there.
  if (!r.viscous->partial) std::remove(ckpt.c_str());
  if (!quiet) std::fputs(summary_text(r, c.output.file).c_str(), stdout);
  return r;
}

}  // namespace magnus
