// The scene in the world through the magnus command: a turned flow gives the same coefficients and the
// same flow turned (probed at world points), a rotor sail its thrust and totals in the summary, the JSON
// and the file; potential flow's summary names itself the inviscid bound beside the viscous reference.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "io/hdf5_io.hpp"
#include "io/result_reader.hpp"
#include "support.hpp"

using namespace magnus;
using json = nlohmann::json;

namespace {

std::string write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

std::string scene(const std::string& flow, const std::string& cylinder = "") {
  return "[cylinder]\nradius = 0.1\nspin = 100.0\n" + cylinder + "[flow]\nspeed = 10.0\n" + flow +
         "[grid]\nn_theta = 64\n";
}

json run_json(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string c = write(dir + "/" + name + ".toml", text);
  const auto o = test::magnus_cmd({"run", c, "-o", dir + "/" + name + ".h5", "--json"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  return json::parse(o.out);
}

json probe_json(const std::string& dir, const std::string& file, const std::vector<std::string>& points) {
  std::vector<std::string> args = {"probe", dir + "/" + file, "--json"};
  args.insert(args.end(), points.begin(), points.end());
  const auto o = test::magnus_cmd(args, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  return json::parse(o.out);
}

double value(const json& q) { return q["value"].get<double>(); }

}  // namespace

TEST_CASE("flow.direction 90°: the same C_L, C_D and the flow turned, probed at world points",
          "[app][scene]") {
  const std::string dir = test::temp_dir("scene-direction");
  const json a = run_json(dir, "a", scene(""));
  const json b = run_json(dir, "b", scene("direction = 90.0\n"));
  // Lift is normal to the freestream and drag along it: the coefficients do not see the direction.
  CHECK(value(b["forces"]["cl"]) == value(a["forces"]["cl"]));
  CHECK(value(b["forces"]["cd"]) == value(a["forces"]["cd"]));
  CHECK(value(b["parameters"]["direction"]) == 90.0);
  // The world frame's components of the same force: towards +y, drag D is F_y and lift L is −F_x.
  CHECK(value(b["derived"]["force_world_x"]) == Approx(-value(b["forces"]["lift"])).margin(1e-12));
  CHECK(value(b["derived"]["force_world_y"]) == Approx(value(b["forces"]["drag"])).margin(1e-12));
  CHECK(b["derived"]["force_world_x"]["units"] == "N/m");
  CHECK_FALSE(a["derived"].contains("force_world_x"));  // towards +x they are lift and drag themselves
  // A world point P of the turned flow sees the unturned flow at R(−90°)P, its velocity turned by +90°:
  // u_b(x, y) = R(90°) u_a(y, −x), i.e. (u_x, u_y)_b = (−u_y, u_x)_a; the pressure is the same.
  const std::vector<std::pair<double, double>> pts = {{0.15, 0.05}, {-0.2, 0.13}, {0.03, -0.31}, {0.0, 0.12}};
  std::vector<std::string> pb, pa;
  for (const auto& [x, y] : pts) {
    pb.push_back(std::to_string(x) + "," + std::to_string(y));
    pa.push_back(std::to_string(y) + "," + std::to_string(-x));
  }
  const json qb = probe_json(dir, "b.h5", pb), qa = probe_json(dir, "a.h5", pa);
  REQUIRE(qb["points"].size() == pts.size());
  for (size_t k = 0; k < pts.size(); ++k) {
    INFO("point " << pb[k]);
    const json &B = qb["points"][k], &A = qa["points"][k];
    const double scale = 10.0;  // U, m/s
    CHECK(std::fabs(value(B["u_x"]) + value(A["u_y"])) <= 1e-12 * scale);
    CHECK(std::fabs(value(B["u_y"]) - value(A["u_x"])) <= 1e-12 * scale);
    CHECK(std::fabs(value(B["pressure"]) - value(A["pressure"])) <= 1e-9);
    // θ of the probe is the world angle of the point.
    CHECK(value(B["theta"]) == Approx(std::fmod(std::atan2(pts[k].second, pts[k].first) + 2 * M_PI, 2 * M_PI)));
  }
  // The stored world coordinates and velocities: the node (r_0 = a, θ_0 = 0 from the freestream) is at the
  // world (0, a), and far from the body the flow goes towards +y.
  const ResultFile f(dir + "/b.h5");
  const auto x = f.dataset("/grid/x"), y = f.dataset("/grid/y"), ux = f.dataset("/fields/u_x"),
             uy = f.dataset("/fields/u_y");
  CHECK(x[0] == 0.0);
  CHECK(y[0] == Approx(0.1));
  const size_t far = ux.size() - 1;  // outer ring, last θ
  CHECK(std::fabs(ux[far]) < 1.0);  // the circulation adds Γ/(2πR) = 0.5 m/s across
  CHECK(uy[far] == Approx(10.0).epsilon(0.05));
  const ResultFile fa(dir + "/a.h5");
  CHECK(fa.dataset("/fields/u_x")[far] == Approx(uy[far]).epsilon(1e-12));
  // Read back, a result is in the wind frame again: the unturned result's fields, to round-off.
  const FlowResult ra = read_result(dir + "/a.h5"), rb = read_result(dir + "/b.h5");
  CHECK(rb.c.scene.direction_deg == 90.0);
  REQUIRE(rb.fields.u_x.size() == ra.fields.u_x.size());
  CHECK(test::max_abs_diff(rb.fields.u_x, ra.fields.u_x) <= 1e-13 * test::max_abs(ra.fields.u_x));
  CHECK(test::max_abs_diff(rb.fields.u_y, ra.fields.u_y) <= 1e-13 * test::max_abs(ra.fields.u_x));
}

TEST_CASE("rotor sail: thrust and side force along the course, totals over the span", "[app][scene]") {
  const std::string dir = test::temp_dir("scene-rotor");
  const std::string text = scene("direction = 90.0\ncourse = 0.0\n", "span = 30.0\n");
  const json j = run_json(dir, "r", text);
  const double lift = value(j["forces"]["lift"]), drag = value(j["forces"]["drag"]);
  REQUIRE(lift < 0.0);  // CCW spin in a flow towards +y: lift towards +x, i.e. ahead
  CHECK(value(j["forces"]["thrust"]) == Approx(-lift).epsilon(1e-14));
  CHECK(value(j["forces"]["side_force"]) == Approx(drag).margin(1e-12));
  CHECK(value(j["forces"]["lift_total"]) == Approx(30.0 * lift).epsilon(1e-14));
  CHECK(value(j["forces"]["thrust_total"]) == Approx(-30.0 * lift).epsilon(1e-14));
  CHECK(j["forces"]["thrust_total"]["units"] == "N");
  CHECK(j["forces"]["thrust"]["units"] == "N/m");
  CHECK(j["parameters"]["span"]["units"] == "m");
  CHECK(j["parameters"]["course"]["units"] == "degree");
  CHECK_FALSE(j["forces"].contains("torque_total"));  // potential flow has no torque
  // The file holds them with units; the summary shows them.
  const ResultFile f(dir + "/r.h5");
  CHECK(f.attr_double("/forces", "thrust_total") == value(j["forces"]["thrust_total"]));
  CHECK(f.attr_string("/forces", "thrust_total_units") == "N");
  const auto o = test::magnus_cmd({"run", dir + "/r.toml", "-o", dir + "/r.h5"}, dir);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("course         0°: thrust ") != std::string::npos);
  CHECK(o.out.find("span           b = 30 m: lift ") != std::string::npos);
  // Without span and course the figures are undefined: null in the JSON, listed in the file.
  const json n = run_json(dir, "n", scene(""));
  CHECK(n["forces"]["thrust"]["value"].is_null());
  CHECK(n["forces"]["lift_total"]["value"].is_null());
  CHECK(n["parameters"]["span"]["value"].is_null());
}

TEST_CASE("shipped rotor sail: the summary gives its 272 kN of thrust", "[app][scene][cases]") {
  const std::string dir = test::temp_dir("scene-shipped");
  const auto o = test::magnus_cmd({"run", std::string(MAGNUS_SOURCE_DIR) + "/cases/rotor_sail.toml", "-o",
                                   dir + "/r.h5"},
                                  dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("thrust 272") != std::string::npos);
  CHECK(o.out.find("(272 kN)") != std::string::npos);
  CHECK(o.out.find("(150 rpm)") != std::string::npos);
}

TEST_CASE("potential flow's summary: the Reynolds number and the inviscid bound beside the reference",
          "[app][scene]") {
  const std::string dir = test::temp_dir("scene-bound");
  // α = 1 at Re = 100: the tabulated Re = 100 points (|C_L| = 2.504, Stojković et al.) are the nearest.
  const std::string c = write(dir + "/c.toml", scene("viscosity = 0.02\n"));
  const auto o = test::magnus_cmd({"run", c, "-o", dir + "/r.h5"}, dir);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("Re = U·2a/ν = 100 (ν = 0.02 m²/s") != std::string::npos);
  CHECK(o.out.find("potential flow is the inviscid upper bound") != std::string::npos);
  CHECK(o.out.find("viscous reference at Re = 100, α = 1: C_L = -2.504") != std::string::npos);
  const auto j = test::magnus_cmd({"run", c, "-o", dir + "/r.h5", "--json"}, dir);
  const json q = json::parse(j.out);
  CHECK(value(q["derived"]["reynolds"]) == Approx(100.0));
  CHECK(value(q["derived"]["reference"]["cl"]) == Approx(-2.504));
  CHECK(value(q["derived"]["reference"]["reynolds"]) == 100.0);
  // Far from the table (α = 3.27) the summary says there is none.
  const std::string far = write(dir + "/f.toml", "[cylinder]\nradius = 0.1\nspin_ratio = 3.27\n[flow]\nspeed = 10.0\n"
                                                 "[grid]\nn_theta = 32\n");
  const auto of = test::magnus_cmd({"run", far, "-o", dir + "/f.h5"}, dir);
  REQUIRE(of.status == 0);
  CHECK(of.out.find("viscous reference: none within") != std::string::npos);
  CHECK(of.out.find("Reynolds") == std::string::npos);  // no viscosity given: no Re
}

TEST_CASE("flow.direction 90°: lift and drag labelled by the flow's frame, the world's F_x, F_y beside",
          "[app][scene]") {
  const std::string dir = test::temp_dir("scene-direction-labels");
  const std::string c = write(dir + "/b.toml", scene("direction = 90.0\n"));
  const auto o = test::magnus_cmd({"run", c, "-o", dir + "/b.h5"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const std::string lift = test::line_of(o.out, "lift "), drag = test::line_of(o.out, "drag ");
  CHECK(lift.find("across the freestream") != std::string::npos);
  CHECK(drag.find("along the freestream") != std::string::npos);
  CHECK(o.out.find("F_y") == o.out.find("F_y = "));  // F_y only as the world component
  CHECK(o.out.find("lift F_y") == std::string::npos);
  CHECK(o.out.find("drag F_x") == std::string::npos);
  const double L = std::stod(lift.substr(15)), D = std::stod(drag.substr(15));
  CHECK(L == Approx(-76.96).epsilon(2e-3));  // −ρUΓ across the freestream, whatever its direction
  // β = 90°: F_x = D cos β − L sin β = −L, F_y = D sin β + L cos β = D.
  const size_t at = o.out.find("force in the world frame: F_x = ");
  REQUIRE(at != std::string::npos);
  const std::string world = o.out.substr(at, o.out.find('\n', at) - at);
  const double Fx = std::stod(world.substr(world.find("F_x = ") + 6));
  const double Fy = std::stod(world.substr(world.find("F_y = ") + 6));
  CHECK(Fx == Approx(-L).epsilon(1e-5));
  CHECK(Fy == Approx(D).margin(1e-6 * std::fabs(L)));
  // Unturned: no world line (the frames agree).
  const auto a = test::magnus_cmd({"run", write(dir + "/a.toml", scene("")), "-o", dir + "/a.h5"}, dir);
  REQUIRE(a.status == 0);
  CHECK(a.out.find("world frame") == std::string::npos);
}

TEST_CASE("run and sweep --set on a scene key replace the case title, other keys and --set title keep it",
          "[app][scene]") {
  const std::string dir = test::temp_dir("scene-retitle");
  const std::string c = std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml";
  auto first_line = [](const std::string& s) { return s.substr(0, s.find('\n')); };
  const auto o = test::magnus_cmd(
      {"run", c, "-o", dir + "/r.h5", "--set", "cylinder.spin=0", "--set", "grid.n_theta=32"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(first_line(o.out).find("Potential flow, spin_ratio_1.toml with --set cylinder.spin=0") !=
        std::string::npos);
  CHECK(o.out.find("spin ratio 1") == std::string::npos);
  CHECK(o.out.find("grid.n_theta") == std::string::npos);  // only the scene's keys are named
  const ResultFile f(dir + "/r.h5");
  CHECK(f.attr_string("/", "title") == "Potential flow, spin_ratio_1.toml with --set cylinder.spin=0");
  CHECK(read_result(dir + "/r.h5").c.title == f.attr_string("/", "title"));
  // Only a grid key: the title stays.
  const auto g = test::magnus_cmd({"run", c, "-o", dir + "/g.h5", "--set", "grid.n_theta=32"}, dir);
  REQUIRE(g.status == 0);
  CHECK(first_line(g.out).find("Spinning cylinder, spin ratio 1") != std::string::npos);
  // A title of one's own is kept.
  const auto t = test::magnus_cmd({"run", c, "-o", dir + "/t.h5", "--set", "cylinder.spin=0", "--set",
                                   "title=\"still\"", "--set", "grid.n_theta=32"},
                                  dir);
  INFO(t.err);
  REQUIRE(t.status == 0);
  CHECK(first_line(t.out).find("— still") != std::string::npos);
  // A sweep is retitled by the user's --set, not by the spin ratio it sets itself.
  const auto s = test::magnus_cmd({"sweep", c, "--spin-ratio", "0:1:0.5", "--set", "flow.speed=5", "--set",
                                   "grid.n_theta=32", "-o", dir + "/s.h5"},
                                  dir);
  INFO(s.err);
  REQUIRE(s.status == 0);
  CHECK(first_line(s.out) == std::string("magnus ") + MAGNUS_VERSION +
                                 " — sweep: Potential flow, spin_ratio_1.toml with --set flow.speed=5");
  CHECK(ResultFile(dir + "/s.h5", std::vector<std::string>{"magnus-sweep"}).attr_string("/", "title") ==
        "Potential flow, spin_ratio_1.toml with --set flow.speed=5");
}
