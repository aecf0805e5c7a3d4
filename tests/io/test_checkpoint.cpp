// Checkpoints of a navier-stokes run read back: the state exactly, the refusal of a checkpoint of another
// scene (naming each parameter that differs, the advection orders among them) and of one that holds a
// non-finite value (naming the dataset). No time stepping: the state is made up on the case's grid.
#include <fmt/core.h>
#include <catch2/catch.hpp>

#include <hdf5.h>

#include <cmath>
#include <functional>
#include <limits>

#include "io/case_parse.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5_io.hpp"
#include "io/schema_files.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// Re 100, α = 1 on a coarse grid (a = 0.5 m, U = 1 m/s: ν = 0.01 m²/s, the time unit D/U is 1 s).
const std::string kCase =
    "[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = 1.0\n[flow]\nspeed = 1.0\n"
    "density = 1.0\nreynolds = 100\n[domain]\nouter_radius = 20.0\n[grid]\nn_theta = 16\n";

/// A made-up checkpoint on the case's grid: three force samples and two snapshots, every value distinct.
Checkpoint made_up(const Case& c) {
  const size_t n = ns_grid(ns_params(c)).nodes();
  Checkpoint cp;
  cp.state.t = 2.5, cp.state.Gamma_R = -0.25, cp.state.Gamma_flux_prev = 1e-3, cp.state.dt_prev = 0.01;
  for (size_t q = 0; q < n; ++q) {
    cp.state.psi.push_back(std::sin(0.1 * double(q)));
    cp.state.zeta.push_back(std::cos(0.1 * double(q)));
    cp.state.N_prev.push_back(1e-3 * double(q));
  }
  for (int k = 0; k < 3; ++k) cp.history.push_back({0.5 * k, true, -2.0 + k, 1.1, 0.1, 0.3, -1.0, 0.05});
  cp.snapshots.push_back({2.0, cp.state.psi, cp.state.zeta});
  cp.snapshots.push_back({2.5, cp.state.zeta, cp.state.psi});
  return cp;
}

/// The message read_checkpoint throws for path and case c ("" when it reads).
std::string refusal(const std::string& path, const Case& c) {
  try {
    read_checkpoint(path, c);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

/// Replace the root attribute `key` of the file at path by text (as an older magnus wrote it).
void set_key(const std::string& path, const std::string& text) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  REQUIRE(H5Adelete(f, "key") >= 0);
  const hid_t t = H5Tcopy(H5T_C_S1), s = H5Screate(H5S_SCALAR);
  H5Tset_size(t, H5T_VARIABLE);
  const char* v = text.c_str();
  const hid_t a = H5Acreate2(f, "key", t, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, t, &v);
  H5Aclose(a), H5Sclose(s), H5Tclose(t);
  REQUIRE(H5Fclose(f) >= 0);
}

}  // namespace

TEST_CASE("checkpoint: a case's own checkpoint reads back exactly", "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-roundtrip"), path = dir + "/r.checkpoint.h5";
  const Case c = test::parse(kCase);
  const Checkpoint cp = made_up(c);
  write_checkpoint(path, c, cp);
  const Checkpoint back = read_checkpoint(path, c);
  CHECK(back.state.t == cp.state.t);
  CHECK(back.state.Gamma_R == cp.state.Gamma_R);
  CHECK(back.state.psi == cp.state.psi);
  CHECK(back.state.zeta == cp.state.zeta);
  CHECK(back.state.N_prev == cp.state.N_prev);
  REQUIRE(back.history.size() == 3);
  CHECK(back.history[2].C_L == 0.0);
  CHECK(back.history[2].M == 0.05);
  REQUIRE(back.snapshots.size() == 2);
  CHECK(back.snapshots[1].psi == cp.state.zeta);
  // The identity names the case keys, the advection orders among them, and (spin: ω ≠ 0) the implicit
  // rotation, whose N_prev is the explicit part only.
  CHECK(checkpoint_key(c) ==
        "cylinder.radius=0.5 flow.speed=1 cylinder.spin=2 cylinder.spin_ratio=1 flow.viscosity=0.01 "
        "flow.reynolds=100 flow.density=1 domain.outer_radius=20 grid.n_theta=16 grid.n_r=14 "
        "solver.advection_order=2 solver.advection_order_xi=2 solver.implicit_rotation=true");
}

TEST_CASE("checkpoint: another advection order is another run, refused", "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-order"), path = dir + "/r.checkpoint.h5";
  const Case c = test::parse(kCase);
  write_checkpoint(path, c, made_up(c));
  CHECK(refusal(path, test::parse(kCase, {"solver.advection_order=4"})) ==
        "checkpoint '" + path +
            "' is from another scene: solver.advection_order 2 there, 4 here; remove it or run without "
            "--resume");
  // Order 4 in ξ keeps the rotation explicit (rotation.hpp): the implicit rotation's entry goes too.
  CHECK(refusal(path, test::parse(kCase, {"solver.advection_order_xi=4"})) ==
        "checkpoint '" + path +
            "' is from another scene: solver.advection_order_xi 2 there, 4 here; solver.implicit_rotation true "
            "there, undefined here; remove it or run without --resume");
  // Jensen's wall closure is another run too; Thom's adds no entry, so older checkpoints still resume.
  CHECK_THAT(checkpoint_key(test::parse(kCase, {"solver.wall_closure=jensen"})),
             Catch::Matchers::EndsWith("solver.advection_order_xi=2 solver.wall_closure=jensen "
                                                       "solver.implicit_rotation=true"));
  CHECK(refusal(path, test::parse(kCase, {"solver.wall_closure=jensen"})) ==
        "checkpoint '" + path +
            "' is from another scene: solver.wall_closure undefined there, jensen here; remove it or run "
            "without --resume");
}

TEST_CASE("checkpoint: the other setting of solver.implicit_rotation is refused, either way", "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-rotation"), path = dir + "/r.checkpoint.h5";
  const std::string why = "; remove it or run without --resume";
  const Case c = test::parse(kCase), off = test::parse(kCase, {"solver.implicit_rotation=false"});
  write_checkpoint(path, c, made_up(c));
  CHECK(refusal(path, off) == "checkpoint '" + path +
                                  "' is from another scene: solver.implicit_rotation true there, undefined here" +
                                  why);
  write_checkpoint(path, off, made_up(off));  // explicit: no entry, as every checkpoint before the key
  CHECK(refusal(path, c) == "checkpoint '" + path +
                                "' is from another scene: solver.implicit_rotation undefined there, true here" +
                                why);
  CHECK(refusal(path, off) == "");
  // Without spin both settings are the one explicit scheme: no entry, either resumes.
  CHECK(checkpoint_key(test::parse(kCase, {"cylinder.spin=0"})) ==
        checkpoint_key(test::parse(kCase, {"cylinder.spin=0", "solver.implicit_rotation=false"})));
}

TEST_CASE("checkpoint: another scene is refused naming each value that differs, there and here",
          "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-scene"), path = dir + "/r.checkpoint.h5";
  const Case c = test::parse(kCase);
  write_checkpoint(path, c, made_up(c));
  const std::string where = "checkpoint '" + path + "' is from another scene: ";
  const std::string what = "; remove it or run without --resume";
  // Re 80: ν = U·2a/Re follows.
  CHECK(refusal(path, test::parse(kCase, {"flow.reynolds=80"})) ==
        where + "flow.viscosity 0.01 there, 0.0125 here; flow.reynolds 100 there, 80 here" + what);
  CHECK(refusal(path, test::parse(kCase, {"cylinder.spin=3"})) ==
        where + "cylinder.spin 2 there, 3 here; cylinder.spin_ratio 1 there, 1.5 here" + what);
  CHECK(refusal(path, test::parse(kCase, {"grid.n_theta=32"})) ==
        where + "grid.n_theta 16 there, 32 here; grid.n_r 14 there, 27 here" + what);
  // U = 0 here: α and Re are undefined here, defined there.
  CHECK(refusal(path, test::parse(kCase, {"flow.speed=0", "flow.viscosity=0.01", "cylinder.spin=2"})) ==
        where +
            "flow.speed 1 there, 0 here; cylinder.spin_ratio 1 there, undefined here; flow.reynolds 100 "
            "there, undefined here" +
            what);
  // time.end, the tolerances and the output may change.
  CHECK(refusal(path, test::parse(kCase, {"time.end=7", "time.mean_tolerance=1e-4", "output.snapshots=3"})) ==
        "");
}

TEST_CASE("checkpoint: one from an older magnus, without the advection orders, is refused",
          "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-older"), path = dir + "/r.checkpoint.h5";
  const Case c = test::parse(kCase);
  write_checkpoint(path, c, made_up(c));
  REQUIRE(refusal(path, c).empty());
  set_key(path, "a=0.5 U=1 omega=2 nu=0.01 rho=1 R/a=20 n_theta=16 n_r=14");
  CHECK(refusal(path, c) ==
        "checkpoint '" + path +
            "' does not record the advection orders (an older magnus wrote it): remove it "
            "or run without --resume");
}

TEST_CASE("checkpoint: a non-finite value anywhere is refused naming its dataset", "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-finite"), path = dir + "/r.checkpoint.h5";
  const Case c = test::parse(kCase);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  // Each spoiled checkpoint and the object its refusal must name.
  const std::vector<std::pair<std::function<void(Checkpoint&)>, std::string>> spoiled = {
      {[&](Checkpoint& cp) { cp.state.zeta[7] = nan; }, "/state/zeta"},
      {[&](Checkpoint& cp) { cp.state.psi[3] = -inf; }, "/state/psi"},
      {[&](Checkpoint& cp) { cp.state.N_prev.back() = inf; }, "/state/N_prev"},
      {[&](Checkpoint& cp) { cp.state.t = nan; }, "/state/t"},
      {[&](Checkpoint& cp) { cp.state.Gamma_R = inf; }, "/state/Gamma_R"},
      {[&](Checkpoint& cp) { cp.state.Gamma_flux_prev = nan; }, "/state/Gamma_flux_prev"},
      {[&](Checkpoint& cp) { cp.state.dt_prev = inf; }, "/state/dt_prev"},
      {[&](Checkpoint& cp) { cp.history[1].t = inf; }, "/history/t"},
      {[&](Checkpoint& cp) { cp.history[2].C_D = inf; }, "/history/cd"},
      {[&](Checkpoint& cp) { cp.history[0].M = nan; }, "/history/torque"},
      {[&](Checkpoint& cp) { cp.snapshots[1].t = nan; }, "/snapshots/t"},
      {[&](Checkpoint& cp) { cp.snapshots[0].psi[5] = inf; }, "/snapshots/psi"},
      {[&](Checkpoint& cp) { cp.snapshots[1].vorticity[0] = nan; }, "/snapshots/vorticity"},
  };
  for (const auto& [spoil, name] : spoiled) {
    Checkpoint cp = made_up(c);
    spoil(cp);
    write_checkpoint(path, c, cp);
    CHECK(refusal(path, c) == "checkpoint '" + path + "': " + name + " holds a non-finite value");
  }
}

TEST_CASE("checkpoint: the file holds the declared table, and steps read back", "[io][checkpoint]") {
  const std::string dir = test::temp_dir("ckpt-table"), path = dir + "/r.checkpoint.h5";
  const Case c = test::parse(kCase);
  Checkpoint cp = made_up(c);
  cp.steps = 1234;
  write_checkpoint(path, c, cp);
  const ResultFile f(path, {"magnus-checkpoint"});
  for (const AttrValue& a : attr_values(checkpoint_attributes(), CheckpointOut{c, cp}, Shown::file_only)) {
    CAPTURE(a.group, a.name);
    REQUIRE(f.has_attr(a.group, a.name));
    CHECK(f.has_attr(a.group, std::string(a.name) + "_units") == (*a.units != '\0'));
  }
  CHECK(f.attr_string("/", "key") == checkpoint_key(c));
  CHECK(f.datasets().size() == checkpoint_datasets().size());
  for (const auto& d : checkpoint_datasets()) {
    CAPTURE(d.path);
    CHECK(f.attr_string(d.path, "units") == d.units);
    CHECK(f.has_attr(d.path, "description") == !d.description.empty());
  }
  CHECK(f.dataset("/snapshots/psi").size() == 2 * cp.state.psi.size());
  CHECK(read_checkpoint(path, c).steps == 1234);
}
