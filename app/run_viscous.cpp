#include "app/run_viscous.hpp"
#include "physics/checked_cast.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>

#include "io/checkpoint.hpp"
#include "io/hdf5_io.hpp"
#include "io/report.hpp"

namespace magnus {

namespace {

volatile std::sig_atomic_t g_stop_signal = 0;  // the signal that asked the march to stop (0: none)

extern "C" void on_stop_signal(int sig) {
  g_stop_signal = sig;
  std::signal(sig, SIG_DFL);  // a second one ends the program at once
}

/// Before the march: Ctrl-C ends the program at once, as by default (also where the shell started it with
/// SIGINT ignored, as it does for a background job).
extern "C" void on_sigint_now(int) {
  std::signal(SIGINT, SIG_DFL);
  std::raise(SIGINT);
}

/// SIGINT (Ctrl-C) and SIGTERM (schedulers, kill) stop the march at the next step while this lives: a
/// partial result and a checkpoint are then written.
struct InterruptGuard {
  InterruptGuard() {
    g_stop_signal = 0;
    previous_int = std::signal(SIGINT, on_stop_signal);
    previous_term = std::signal(SIGTERM, on_stop_signal);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
  }
  void (*previous_int)(int) = SIG_DFL;
  void (*previous_term)(int) = SIG_DFL;
};

std::string clock_text(double seconds) {
  if (!(seconds < 100.0 * 3600.0)) return seconds > 0.0 ? "> 100:00:00" : "?";  // NaN: no estimate
  const long s = saturate_cast<long>(std::max(seconds, 0.0) + 0.5);
  return s >= 3600 ? fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60)
                   : fmt::format("{}:{:02d}", s / 60, s % 60);
}

/// The progress line of the march on stderr: t, the forces, steps/s and the time left.
struct Progress {
  const Case& c;
  double unit, t0;
  std::chrono::steady_clock::time_point clock0 = std::chrono::steady_clock::now(), last = clock0;
  long steps = 0;
  bool printed = false;

  void step(const NsState& s, const ViscousForces& f) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last <= std::chrono::milliseconds(250)) return;
    last = now;
    const double el = std::chrono::duration<double>(now - clock0).count();
    const double rate = el > 0.0 ? (s.t - t0) / el : 0.0;  // simulated s per wall s
    const std::string coeffs = f.C_L ? fmt::format("C_L = {:+.4f}  C_D = {:.4f}", *f.C_L, *f.C_D)
                                     : fmt::format("M = {:+.4g} N·m/m", f.M);
    std::fprintf(stderr, "\r\033[K  t = %.1f %s of %.0f  %s  %.0f steps/s  ETA ≤ %s   ", s.t / unit,
                 time_unit_name(c.scene), c.time.end, coeffs.c_str(), double(steps) / std::max(el, 1e-9),
                 rate > 0.0 ? clock_text((c.time.end * unit - s.t) / rate).c_str() : "?");
    std::fflush(stderr);
    printed = true;
  }
};

/// An argument as the shell reads it back (quoted when it holds anything but plain characters).
std::string shell_word(const std::string& w) {
  if (!w.empty() &&
      w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.,/=+:@%") ==
          std::string::npos)
    return w;
  std::string q = "'";
  for (char ch : w) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

}  // namespace

std::string before_march_text(const Case& c) {
  if (c.model != FlowModel::navier_stokes) return "";  // nothing marches
  if (c.time.mode == TimeMode::steady) return "  solving the steady equations by Newton's method (Ctrl-C stops) …";
  if (c.time.mode != TimeMode::automatic) return "";
  const AutoPlan plan = auto_plan(ns_params(c));
  switch (plan.start) {
    case AutoStart::march:
      return "";  // the march's own progress line follows at once
    case AutoStart::newton_only:
      return "  auto: steady flow (" + plan.why + "): solving by Newton's method (Ctrl-C stops) …";
    case AutoStart::search:
      break;
  }
  return "  auto: looking for a stable steady state (Newton's method, eigenvalues; Ctrl-C stops) …";
}

std::string resume_command(const std::string& case_path, const std::string& output) {
  return fmt::format("magnus run {} -o {} --resume", shell_word(case_path), shell_word(output));
}

namespace {

/// The summary on stdout (unless quiet; a partial result's names its checkpoint and the command that goes
/// on), and for a run stopped by signal `sig` (else 0) one line on stderr saying so.
void report_run(const FlowResult& r, const Case& c, const std::string& case_path, bool quiet, int sig) {
  const std::string& out = c.output.file;
  if (!quiet) {
    std::string text = summary_text(r, out);
    if (r.viscous && r.viscous->partial)
      text += fmt::format("{:<15}{} — go on with: {}\n", "checkpoint", checkpoint_path(out),
                          resume_command(case_path, out));
    std::fputs(text.c_str(), stdout);
  }
  if (sig)
    std::fprintf(stderr, "magnus: interrupted by %s at t = %.4g %s: a partial result; go on with: %s\n",
                 sig == SIGTERM ? "SIGTERM" : "SIGINT", r.viscous->t / r.viscous->time_unit,
                 time_unit_name(c.scene), resume_command(case_path, out).c_str());
}

/// run_case with, for a navier-stokes case, Ctrl-C ending the program at once until the march installs its
/// guard; the guard removed after the run (or its failure) and the progress line ended.
FlowResult run_guarded(const Case& c, const RunHooks& hooks, std::optional<InterruptGuard>& guard,
                       const Progress& progress) {
  const bool marches = c.model == FlowModel::navier_stokes;
  void (*before_march)(int) = marches ? std::signal(SIGINT, on_sigint_now) : SIG_DFL;
  auto restore = [&] {
    guard.reset();
    if (marches) std::signal(SIGINT, before_march);
    if (progress.printed) std::fputs("\n", stderr);
  };
  try {
    FlowResult r = run_case(c, hooks);
    restore();
    return r;
  } catch (...) {
    restore();
    throw;
  }
}

}  // namespace

FlowResult run_and_report(const Case& c, const std::string& case_path, bool resume, bool quiet,
                          RunHooks hooks, int* stopped_by) {
  const std::string ckpt = checkpoint_path(c.output.file);
  std::unique_ptr<Checkpoint> start;
  if (resume) start = std::make_unique<Checkpoint>(read_checkpoint(ckpt, c));
  hooks.resume = start.get();

  const double unit = c.scene.time_unit();
  Progress progress{c, unit, start ? start->state.t : 0.0};
  const bool show = !quiet && isatty(STDERR_FILENO);

  // SIGINT and SIGTERM stop the march at the next step with a partial result; before the march (the Newton
  // solve and stability test of time.mode "steady" or "auto") nothing is computed yet that a result could
  // keep, so there they end the program at once: the handlers are installed with the first step.
  std::optional<InterruptGuard> guard;
  hooks.viscous.on_step = [&](const NsState& s, const ViscousForces& f) {
    if (!guard) guard.emplace();
    ++progress.steps;
    if (show) progress.step(s, f);
    return g_stop_signal == 0;
  };
  hooks.viscous.keep_going = [] { return g_stop_signal == 0; };
  // The checkpoint this run may remove once its result is complete: the one it resumed from or wrote, never
  // another run's. One that cannot be written (a full disk) is a warning: the run goes on, the last good
  // checkpoint stays.
  bool own_checkpoint = resume;
  std::string last_failure;  // warned once for each new reason
  hooks.viscous.on_checkpoint = [&](const Checkpoint& cp) {
    try {
      write_checkpoint(ckpt, c, cp);
      own_checkpoint = true;
      last_failure.clear();
    } catch (const std::exception& e) {
      if (e.what() == last_failure) return;
      last_failure = e.what();
      std::fprintf(stderr, "%smagnus: warning: no checkpoint at t = %.4g %s (%s); the run goes on%s\n",
                   progress.printed ? "\n" : "", cp.state.t / unit, time_unit_name(c.scene), e.what(),
                   own_checkpoint ? ", the previous checkpoint stays" : "");
    }
  };

  // The line names what will run: "auto" marches at once where shedding is certain (no Newton to announce).
  if (show && !start && c.time.mode != TimeMode::unsteady) {
    const std::string text = before_march_text(c);
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
    progress.printed = !text.empty();
  }
  FlowResult r = run_guarded(c, hooks, guard, progress);
  write_result(r, c.output.file, c.output.compression);
  // Complete: the checkpoint has served. Interrupted: run_viscous checkpointed the last state, so
  // --resume goes on from there.
  const bool partial = r.viscous && r.viscous->partial;
  if (!partial && own_checkpoint) std::remove(ckpt.c_str());
  const int sig = partial ? int(g_stop_signal) : 0;
  if (stopped_by) *stopped_by = sig;
  report_run(r, c, case_path, quiet, sig);
  return r;
}

}  // namespace magnus
