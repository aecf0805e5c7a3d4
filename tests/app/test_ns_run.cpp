// magnus run on navier-stokes cases: the result file and summary, bad input, Ctrl-C (a partial result and
// a checkpoint), a killed run resumed from its checkpoint. Coarse grids: each run takes well under a second.
#include <fmt/core.h>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/case_file.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5_io.hpp"
#include "io/result_reader.hpp"
#include "app/run_viscous.hpp"
#include "postproc/navier_stokes/resolution.hpp"
#include "run_child.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// A navier-stokes case at Re, α on a coarse grid (a = 0.5 m, U = 1 m/s: the time unit D/U is 1 s).
std::string ns_case(double Re, double alpha, double t_end, const std::string& more = "") {
  return fmt::format(
      "title = \"test\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = {}\n"
      "[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = {}\n[domain]\nouter_radius = 40.0\n[grid]\n"
      "n_theta = 48\n[time]\nend = {}\n{}",
      alpha, Re, t_end, more);
}

std::string write_case(const std::string& dir, const std::string& text) {
  const std::string path = dir + "/case.toml";
  std::ofstream(path) << text;
  return path;
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

}  // namespace

TEST_CASE("navier-stokes run: the result holds the viscous figures, the summary puts them beside the ideal",
          "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run");
  const auto o = test::magnus_cmd({"run", write_case(dir, ns_case(100, 1, 20)), "-o", dir + "/r.h5"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  for (const char* label : {"viscous (this run)", "ideal (potential flow", "S/(2πρa²)", "Re = U·2a/ν = 100",
                            "advection order 2 in θ"})
    CHECK(o.out.find(label) != std::string::npos);
  CHECK(o.out.find("three-dimensional") == std::string::npos);
  const FlowResult r = read_result(dir + "/r.h5");
  REQUIRE(r.viscous);
  REQUIRE(r.c.model == FlowModel::navier_stokes);
  const ViscousPart& v = *r.viscous;
  REQUIRE(v.t == Approx(20.0));  // D/U = 1 s
  REQUIRE_FALSE(v.partial);
  REQUIRE(v.history.size() == size_t(v.steps) + 1);
  // The ideal lift of the same scene is −2πα exactly; the measured share S/(2πρa²) is C_L,mean over it.
  REQUIRE(*v.cl_ideal == Approx(-2.0 * M_PI).epsilon(1e-14));
  REQUIRE(*v.magnus_ratio == Approx(*v.cl_mean / *v.cl_ideal).epsilon(1e-14));
  // Counter-clockwise spin lifts towards −y, less than the ideal: 0 < S/(2πρa²) < 1.
  REQUIRE(*v.cl_mean < 0.0);
  REQUIRE(*v.magnus_ratio > 0.0);
  REQUIRE(*v.magnus_ratio < 1.0);
  // The last step's parts add up to the whole.
  REQUIRE(*v.last.C_D_pressure + *v.last.C_D_friction == Approx(*r.forces.cd).epsilon(1e-12));
  REQUIRE(*v.last.C_L_pressure + *v.last.C_L_friction == Approx(*r.forces.cl).epsilon(1e-12));
  REQUIRE(r.fields.vorticity.size() == size_t(r.grid.nodes()));
  REQUIRE(r.surface.shear_stress.size() == size_t(r.grid.n_theta));
  // No checkpoint is left behind by a complete run.
  REQUIRE_FALSE(exists(checkpoint_path(dir + "/r.h5")));
}

TEST_CASE("navier-stokes run: solver.advection_order = 4 is used, stated and stored", "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-order4");
  // One run of the Re 100, α = 1 case to `out` with the given --set overrides.
  auto run = [&](const std::string& out, const std::vector<std::string>& sets) {
    std::vector<std::string> args = {"run", write_case(dir, ns_case(100, 1, 2)), "-o", dir + "/" + out};
    for (const std::string& s : sets) args.push_back("--set"), args.push_back(s);
    return test::magnus_cmd(args, dir);
  };
  const auto o = run("r.h5", {"solver.advection_order=4"});
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("advection order 4 in θ, 2 in ξ") != std::string::npos);
  const FlowResult r = read_result(dir + "/r.h5");
  CHECK(r.c.solver.advection_order == 4);
  CHECK(r.c.solver.advection_order_xi == 2);
  // The time step follows the CFL number with the fourth-order difference's wavenumber (1.3722 in θ):
  // shorter than order 2's on the same case.
  REQUIRE(run("r2.h5", {}).status == 0);
  const FlowResult r2 = read_result(dir + "/r2.h5");
  CHECK(r.viscous->steps > r2.viscous->steps);
  // Order 4 in ξ as well: stated, stored, and run (the CFL number's ξ part scaled likewise).
  const auto o4 = run("r4.h5", {"solver.advection_order=4", "solver.advection_order_xi=4"});
  INFO(o4.err);
  REQUIRE(o4.status == 0);
  CHECK(o4.out.find("advection order 4 in θ, 4 in ξ") != std::string::npos);
  const FlowResult r4 = read_result(dir + "/r4.h5");
  CHECK(r4.c.solver.advection_order_xi == 4);
  CHECK(r4.viscous->steps >= r.viscous->steps);
}

TEST_CASE("navier-stokes run: at Re 250 no fixed rule, the summary says the 3D onset is not computed",
          "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-3d");
  const auto o = test::magnus_cmd({"run", write_case(dir, ns_case(250, 0.5, 2)), "-o", dir + "/r.h5"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("whether this 2D flow is real is not computed for this run") != std::string::npos);
  // S/(2πρa²) is the 2D laminar model's figure, not claimed as what a real cylinder gets.
  CHECK(o.out.find("a real cylinder gets") == std::string::npos);
  CHECK(o.out.find("the 2D laminar model's share of the ideal lift at Re = 250") != std::string::npos);
}

TEST_CASE("navier-stokes run: a scene no grid in memory resolves is refused up front in one line",
          "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-unresolvable");
  // Re 1e8 at α 3: the boundary layer D/√(Re(1 + α²)) = 3.2e-5 D needs some 1e10 nodes for two wall cells.
  const auto o = test::magnus_cmd(
      {"run", write_case(dir, ns_case(1e8, 3, 5, "mode = \"unsteady\"\n")), "-o", dir + "/r.h5"}, dir);
  REQUIRE(o.status != 0);
  REQUIRE(test::lines(o.err) == 1);
  CHECK(o.err.find("flow.reynolds: Re = 1e+08 at α = 3") != std::string::npos);
  CHECK(o.err.find("beyond what the 2D laminar model can resolve") != std::string::npos);
  CHECK(o.err.find("data/rotor_data.toml") != std::string::npos);
  REQUIRE_FALSE(exists(dir + "/r.h5"));
  const auto st = test::magnus_cmd({"stability", dir + "/case.toml"}, dir);
  REQUIRE(st.status != 0);
  CHECK(st.err.find("beyond what the 2D laminar model can resolve") != std::string::npos);
  // The rotor sail's own scene (Re 4e6, α 3.27) needs tens of GB: refused below that, not below 1 TB.
  Case c = parse_case(ns_case(4e6, 3.27, 5), "rotor.toml");
  const ResolvingGrid g = resolving_grid(c, kWallCellsNeeded);
  CHECK(g.n_theta > 10000);
  CHECK(g.bytes > 20e9);
  CHECK_THROWS_AS(check_resolvable(c, size_t(16) << 30), std::invalid_argument);
  CHECK_NOTHROW(check_resolvable(c, size_t(1) << 40));
  // Re 100, α 1: one wall cell on n_θ 30 (the default 192 has 7.1), and never refused.
  c = parse_case(ns_case(100, 1, 5), "c.toml");
  CHECK(resolving_grid(c, 1.0).n_theta == 30);
  CHECK_NOTHROW(check_resolvable(c, size_t(64) << 20));
}

TEST_CASE("navier-stokes run: unresolved forces get the verdict first and no S finding", "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-unresolved");
  // α = 50 at Re 100 on n_θ 48: 0.05 wall cells (a grid of n_θ ≈ 950 would have one).
  const auto o = test::magnus_cmd(
      {"run", write_case(dir, ns_case(100, 50, 0.2, "mode = \"unsteady\"\n")), "-o", dir + "/r.h5"}, dir);
  INFO(o.out << o.err);
  REQUIRE(o.status == 0);
  const size_t verdict = o.out.find("verdict        NOT RESOLVED:"), grid = o.out.find("\ngrid ");
  REQUIRE(verdict != std::string::npos);
  CHECK(verdict < grid);
  CHECK(o.out.find("the forces below are not meaningful (grid.n_theta ≥ ") != std::string::npos);
  CHECK(o.out.find("a real cylinder gets") == std::string::npos);
  CHECK(o.out.find("not meaningful: the boundary layer is not resolved") != std::string::npos);
}

TEST_CASE("navier-stokes auto: the progress line announces only what runs", "[app][ns]") {
  const auto line = [](double Re, double alpha, const char* mode) {
    return before_march_text(parse_case(ns_case(Re, alpha, 5, fmt::format("mode = \"{}\"\n", mode)), "c.toml"));
  };
  CHECK(line(100, 0.5, "auto").empty());  // it marches at once: no Newton search to announce
  CHECK(line(100, 0.5, "unsteady").empty());
  CHECK(line(20, 0.5, "auto").find("Newton") != std::string::npos);
  CHECK(line(20, 0.5, "auto").find("eigenvalues") == std::string::npos);
  CHECK(line(100, 3, "auto").find("eigenvalues") != std::string::npos);
  CHECK(line(100, 0.5, "steady").find("Newton") != std::string::npos);
}

TEST_CASE("navier-stokes run: a time step above the stability limit is one line and no output", "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-dt");
  const auto o =
      test::magnus_cmd({"run", write_case(dir, ns_case(100, 1, 5, "dt = 0.5\n")), "-o", dir + "/r.h5"}, dir);
  REQUIRE(o.status != 0);
  REQUIRE(test::lines(o.err) == 1);
  REQUIRE(o.err.find("time.dt = 0.5") != std::string::npos);
  REQUIRE(o.err.find("stability limit") != std::string::npos);
  REQUIRE_FALSE(exists(dir + "/r.h5"));
  REQUIRE_FALSE(exists(dir + "/r.xmf"));
}

TEST_CASE("navier-stokes run: Ctrl-C writes a partial result and a checkpoint, --resume finishes the run",
          "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-int");
  // A run that would not stop by itself (its means never agree to 1e-12, steadiness is not a stop).
  const std::string c = write_case(
      dir,
      ns_case(100, 1, 100000, "mode = \"unsteady\"\nmean_tolerance = 1e-12\ncheckpoint_interval = 1.0\n"));
  const std::string ckpt = checkpoint_path(dir + "/r.h5");
  // SIGINT once the first checkpoint (t = 1 D/U) exists, so the run is stepping whatever the machine's load
  // (a fixed delay raced the start-up on a busy machine); it stops at the next step, writes its partial
  // result and checkpoint and exits 130 (128 + SIGINT), as a shell reports Ctrl-C.
  const std::string cmd =
      "'" + std::string(MAGNUS_EXE) + "' run '" + c + "' -o '" + dir + "/r.h5' >'" + dir + "/out.txt' 2>'" +
      dir + "/err.txt' & pid=$!; i=0; while [ ! -e '" + ckpt +
      "' ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done; kill -INT $pid; wait $pid";
  const int raw = std::system(cmd.c_str());
  INFO(test::slurp(dir + "/err.txt"));
  REQUIRE(WIFEXITED(raw));
  REQUIRE(WEXITSTATUS(raw) == 130);
  const FlowResult part = read_result(dir + "/r.h5");
  REQUIRE(part.viscous->partial);
  REQUIRE(part.viscous->status.find("interrupted") != std::string::npos);
  REQUIRE(ResultFile(dir + "/r.h5").attr_int("/", "partial") == 1);
  REQUIRE(test::slurp(dir + "/out.txt").find("PARTIAL") != std::string::npos);
  // The summary names the checkpoint and the command that goes on from it.
  REQUIRE(test::slurp(dir + "/out.txt")
              .find("checkpoint     " + ckpt + " — go on with: magnus run " + c + " -o " + dir +
                    "/r.h5 --resume\n") != std::string::npos);
  REQUIRE(exists(ckpt));
  const double t_stop = part.viscous->t;
  REQUIRE(t_stop > 1.0);
  // Resume with a reachable end: the history goes on from the interruption, one sample per step.
  const double t_end = t_stop + 3.0;
  const auto o = test::magnus_cmd(
      {"run", c, "-o", dir + "/r.h5", "--resume", "--set", fmt::format("time.end={}", t_end)}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const FlowResult done = read_result(dir + "/r.h5");
  REQUIRE_FALSE(done.viscous->partial);
  REQUIRE(done.viscous->t == Approx(t_end));
  REQUIRE(done.viscous->history.front().t == 0.0);
  for (size_t q = 1; q < done.viscous->history.size(); ++q)
    REQUIRE(done.viscous->history[q].t > done.viscous->history[q - 1].t);
  REQUIRE_FALSE(exists(ckpt));
}

TEST_CASE(
    "navier-stokes run: a killed run resumes from its last checkpoint and ends where an unbroken one does",
    "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-kill");
  const std::string c = write_case(dir, ns_case(100, 1, 12, "checkpoint_interval = 2.0\n"));
  const auto whole = test::magnus_cmd({"run", c, "-o", dir + "/whole.h5"}, dir);
  REQUIRE(whole.status == 0);
  // SIGKILL from here as soon as a checkpoint at t ≥ 4 D/U is there: no clean-up of any kind.
  const std::string ckpt = checkpoint_path(dir + "/k.h5");
  const test::Running run = test::start_magnus({"run", c, "-o", dir + "/k.h5"}, dir);
  test::signal_after_checkpoint(run, ckpt, 4.0, SIGKILL);
  const test::Ended killed = test::wait_magnus(run);
  REQUIRE_FALSE(killed.exited);
  REQUIRE(killed.status == SIGKILL);
  REQUIRE_FALSE(exists(dir + "/k.h5"));  // nothing half-written
  REQUIRE(exists(ckpt));
  const FlowResult whole_r = read_result(dir + "/whole.h5");
  const Checkpoint cp = read_checkpoint(ckpt, load_case(c, {}));
  REQUIRE(cp.state.t >= 4.0);
  REQUIRE(cp.state.t < 12.0);
  const auto o = test::magnus_cmd({"run", c, "-o", dir + "/k.h5", "--resume"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const FlowResult resumed = read_result(dir + "/k.h5");
  REQUIRE(resumed.viscous->t == Approx(12.0));
  // The same flow: the restart only re-picks Δt from the CFL number (an O(Δt²) difference).
  // Up to the checkpoint the resumed run's history is the unbroken run's, sample for sample (to round-off:
  // FFTW may pick other SIMD code paths for differently aligned arrays in another process).
  const auto& hw = whole_r.viscous->history;
  const auto& hr = resumed.viscous->history;
  size_t same = 0;
  for (; same < hr.size() && hr[same].t <= cp.state.t; ++same) {
    REQUIRE(hr[same].t == Approx(hw[same].t).epsilon(1e-12));
    REQUIRE(hr[same].C_L == Approx(hw[same].C_L).margin(1e-9));
    REQUIRE(hr[same].C_D == Approx(hw[same].C_D).margin(1e-9));
    REQUIRE(hr[same].M == Approx(hw[same].M).margin(1e-9));
  }
  REQUIRE(same > 100);
  REQUIRE(*resumed.forces.cl == Approx(*whole_r.forces.cl).epsilon(2e-3));
  REQUIRE(*resumed.forces.cd == Approx(*whole_r.forces.cd).epsilon(2e-3));
  REQUIRE_FALSE(exists(ckpt));
  // The complete run removed its checkpoint: --resume again has nothing to go on from, and says so in one
  // line (a checkpoint of another scene: tests/app/test_ns_resume.cpp).
  const auto none =
      test::magnus_cmd({"run", c, "-o", dir + "/k.h5", "--set", "time.end=20", "--resume"}, dir);
  REQUIRE(none.status != 0);
  REQUIRE(test::lines(none.err) == 1);
  REQUIRE(none.err.find("--resume: cannot read '" + ckpt + "'") != std::string::npos);
}

TEST_CASE("navier-stokes: sweep --circulation refuses in one line, a potential run refuses --resume",
          "[app][ns]") {
  const std::string dir = test::temp_dir("ns-sweep");
  const auto s =
      test::magnus_cmd({"sweep", write_case(dir, ns_case(100, 1, 5)), "--circulation", "0:1:0.5"}, dir);
  REQUIRE(s.status != 0);
  REQUIRE(test::lines(s.err) == 1);
  REQUIRE(s.err.find("navier-stokes") != std::string::npos);
  std::ofstream(dir + "/p.toml")
      << "[cylinder]\nradius = 0.1\nspin = 1.0\n[flow]\nspeed = 1.0\n[grid]\nn_theta = 16\n";
  const auto r = test::magnus_cmd({"run", dir + "/p.toml", "-o", dir + "/p.h5", "--resume"}, dir);
  REQUIRE(r.status != 0);
  REQUIRE(test::lines(r.err) == 1);
  REQUIRE(r.err.find("--resume") != std::string::npos);
  REQUIRE_FALSE(exists(dir + "/p.h5"));
}

TEST_CASE("navier-stokes bench: the step cost per grid, split into its parts", "[app][ns][bench]") {
  const std::string dir = test::temp_dir("ns-bench");
  const auto o = test::magnus_cmd({"bench", write_case(dir, ns_case(100, 1, 5)), "--ladder", "32,64",
                                   "--steps", "30", "--csv", dir + "/b.csv"},
                                  dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  for (const char* part : {"advection", "diffusion", "Poisson", "wall", "forces", "steps/s", "ns/node"})
    CHECK(o.out.find(part) != std::string::npos);
  // The bound line: bytes per node, the measured bandwidth and their quotient, finite and consistent
  // (ns/node = bytes / (GB/s)); its values are data, not checked against a timing.
  const size_t at = o.out.find("The step moves about ");
  REQUIRE(at != std::string::npos);
  double bytes = 0, gbs = 0, bound = 0;
  REQUIRE(std::sscanf(o.out.c_str() + at, "The step moves about %lf bytes per node: at the measured %lf GB/s", &bytes,
                      &gbs) == 2);
  const size_t less = o.out.find("less than ", at);
  REQUIRE(less != std::string::npos);
  REQUIRE(std::sscanf(o.out.c_str() + less, "less than %lf ns/node", &bound) == 1);
  REQUIRE(bytes > 0.0);
  REQUIRE(std::isfinite(gbs));
  REQUIRE(gbs > 0.0);
  CHECK(bound == Approx(bytes / gbs).epsilon(0.02));  // both printed to 3 significant digits
  const std::string bound_line = o.out.substr(at, o.out.find('\n', at) - at);
  CHECK(bound_line.find("nan") == std::string::npos);
  CHECK(bound_line.find("inf") == std::string::npos);
  const std::string csv = test::slurp(dir + "/b.csv");
  REQUIRE(test::lines(csv) == 3);  // header + two grids
  // Each row: the parts (ms per step) are measured inside the step, so they add up to at most the step's
  // wall time, and every part is a real share of it.
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 15);
    REQUIRE(v[5] == 30);  // steps
    REQUIRE(v[14] > 0.0);  // ns per node per step
    CHECK(v[14] == Approx(1e6 * v[7] / v[2]).epsilon(1e-4));  // = ms/step over the nodes
    double sum = 0.0;
    for (size_t k = 8; k < 14; ++k) {
      REQUIRE(v[k] >= 0.0);
      sum += v[k];
    }
    REQUIRE(sum <= v[7] * 1.001);
    REQUIRE(sum >= 0.5 * v[7]);
  }
  const auto bad =
      test::magnus_cmd({"bench", write_case(dir, ns_case(100, 1, 5)), "--plot", dir + "/p.png"}, dir);
  REQUIRE(bad.status != 0);
  REQUIRE(test::lines(bad.err) == 1);
}

TEST_CASE("navier-stokes run at U = 0: the torque tends to the potential vortex's, no coefficients",
          "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-still");
  std::ofstream(dir + "/c.toml")
      << "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin = 2.0\n"
         "[flow]\nspeed = 0.0\ndensity = 1.0\nviscosity = 0.05\n[domain]\n"
         "outer_radius = 8.0\n[grid]\nn_theta = 32\n[time]\nend = 400.0\n";
  const auto o = test::magnus_cmd({"run", dir + "/c.toml", "-o", dir + "/r.h5"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  REQUIRE(o.out.find("steady potential vortex") != std::string::npos);
  const ResultFile f(dir + "/r.h5");
  for (const char* undefined : {"cl", "cd", "cl_mean", "strouhal", "magnus_ratio"})
    REQUIRE_FALSE(f.has_attr("/forces", undefined));
  // M = −4πμa²ω: the steady potential vortex u_θ = a²ω/r (μ = ρν).
  const double exact = -4.0 * M_PI * 0.05 * 0.25 * 2.0;
  REQUIRE(f.attr_double("/forces", "torque_mean") == Approx(exact).epsilon(0.02));
  REQUIRE(f.attr_double("/forces", "spin_power_mean") == Approx(-exact * 2.0).epsilon(0.02));
}

TEST_CASE("navier-stokes run in steady mode: Newton's state is the time stepper's steady state",
          "[app][ns][newton]") {
  const std::string dir = test::temp_dir("ns-run-steady");
  const std::string steady = write_case(dir, ns_case(20, 0.5, 400, "mode = \"steady\"\n"));
  const auto n = test::magnus_cmd({"run", steady, "-o", dir + "/n.h5"}, dir);
  INFO(n.err);
  REQUIRE(n.status == 0);
  REQUIRE(n.out.find("steady state by Newton's method") != std::string::npos);
  std::ofstream(dir + "/m.toml") << ns_case(20, 0.5, 400, "mode = \"auto\"\n");
  const auto m = test::magnus_cmd({"run", dir + "/m.toml", "-o", dir + "/m.h5"}, dir);
  REQUIRE(m.status == 0);
  const FlowResult a = read_result(dir + "/n.h5"), b = read_result(dir + "/m.h5");
  REQUIRE(a.viscous->status.find("steady, by Newton") == 0);
  // "auto" solves by Newton too; at Re 20 steady flow is certain (below the onset of shedding), so it skips
  // the eigenvalue test and says so, with the time Newton took.
  INFO(b.viscous->status);
  REQUIRE(b.viscous->status.find("auto: steady (Re 20 ≤ 35, α 0.5 ≤ 3: below the onset of shedding") == 0);
  REQUIRE(b.viscous->status.find("no eigenvalue test") != std::string::npos);
  REQUIRE(b.viscous->status.find("steady, by Newton") != std::string::npos);
  REQUIRE(!b.viscous->eigenvalue_real.has_value());
  REQUIRE(!b.viscous->stability_seconds.has_value());
  REQUIRE(b.viscous->newton_seconds.has_value());
  REQUIRE(*b.viscous->newton_seconds > 0.0);
  REQUIRE(m.out.find("steady state by Newton's method") != std::string::npos);
  REQUIRE(m.out.find(": Newton ") != std::string::npos);
  REQUIRE(*a.viscous->cl_mean == Approx(*b.viscous->cl_mean).margin(1e-9));
  REQUIRE(*a.viscous->cd_mean == Approx(*b.viscous->cd_mean).margin(1e-9));
  REQUIRE(!a.viscous->eigenvalue_real.has_value());  // "steady" does not compute it: undefined
  REQUIRE(a.viscous->history.size() == 1);
}

TEST_CASE("navier-stokes run: time.stop_on_drift = false stops on agreement alone, sooner", "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-drift");
  const std::string c = std::string(MAGNUS_SOURCE_DIR) + "/cases/re100_alpha1.toml";
  // Re 100, α 1 on n_θ 32, R = 20a, means to 2e-5: the drift of the means is what holds the run back.
  auto run = [&](const char* drift, const std::string& out) {
    return test::magnus_cmd({"run", c, "-o", dir + "/" + out, "--set", "grid.n_theta=32", "--set",
                             "domain.outer_radius=20", "--set", "time.mean_tolerance=2e-5", "--set",
                             std::string("time.stop_on_drift=") + drift},
                            dir);
  };
  REQUIRE(run("true", "on.h5").status == 0);
  const auto off = run("false", "off.h5");
  INFO(off.err);
  REQUIRE(off.status == 0);
  const FlowResult on_r = read_result(dir + "/on.h5"), off_r = read_result(dir + "/off.h5");
  // Both converged; without the drift rule it stopped periods earlier.
  CHECK(on_r.viscous->status.find("periodic means converged") != std::string::npos);
  CHECK(off_r.viscous->status.find("periodic means converged") != std::string::npos);
  CHECK(off_r.viscous->steps < on_r.viscous->steps);
  // The key is kept in the stored case (absent when true, the default), and the bars still carry the drift.
  CHECK(off_r.c.source_text.find("stop_on_drift = false") != std::string::npos);
  CHECK(on_r.c.source_text.find("stop_on_drift") == std::string::npos);
  CHECK(off_r.viscous->cd_mean_drift_rel.has_value());
  // Not a boolean: one line naming the key.
  const auto bad = run("maybe", "bad.h5");
  CHECK(bad.status != 0);
  CHECK(test::lines(bad.err) == 1);
  CHECK(bad.err.find("time.stop_on_drift") != std::string::npos);
}

TEST_CASE("navier-stokes run: grid.tolerance T holds a periodic run's means to T/5", "[app][ns]") {
  const std::string dir = test::temp_dir("ns-run-t5");
  const std::string c = std::string(MAGNUS_SOURCE_DIR) + "/cases/re100_alpha1.toml";
  // T = 0.1 picks a coarse grid (64 × 79 on R = 20a); time.mean_tolerance 0.05 is looser than T/5 = 0.02.
  const auto o = test::magnus_cmd({"run", c, "-o", dir + "/r.h5", "--set", "grid.tolerance=0.1", "--set",
                                   "time.mean_tolerance=0.05", "--set", "domain.outer_radius=20"},
                                  dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const FlowResult r = read_result(dir + "/r.h5");
  CHECK(r.viscous->status.find("periodic means converged (to 0.02: a fifth of grid.tolerance)") !=
        std::string::npos);
  // What the stop rule held: the drift still to come of each mean is below T/5 (relative; |C_L|, C_D ≥ 1).
  for (const auto& d : {r.viscous->cl_mean_drift_rel, r.viscous->cd_mean_drift_rel, r.viscous->strouhal_drift_rel}) {
    REQUIRE(d);
    CHECK(*d < 0.02);
  }
  // A mean_tolerance already below T/5 is kept, and the status says nothing of T.
  const auto tight = test::magnus_cmd({"run", c, "-o", dir + "/t.h5", "--set", "grid.tolerance=0.1", "--set",
                                       "time.mean_tolerance=0.01", "--set", "domain.outer_radius=20"},
                                      dir);
  REQUIRE(tight.status == 0);
  CHECK(read_result(dir + "/t.h5").viscous->status.find("a fifth of grid.tolerance") == std::string::npos);
}
