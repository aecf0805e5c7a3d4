// --json on run, sweep, compare and inspect; inspect --surface-csv. The JSON parses, every number carries
// its units ({"value": V, "units": U}), undefined is null, and every line of the run summary has its
// counterpart in the JSON (the mapping below, label by label).
#include <fmt/core.h>
#include <fmt/format.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "solver/navier_stokes/stability.hpp"
#include "support.hpp"

using namespace magnus;
using nlohmann::json;

namespace {

const std::string kPotentialCase =
    "title = \"json test\"\n[cylinder]\nradius = 0.1\nspin_ratio = 1.0\nspan = 2.0\n[flow]\nspeed = 10.0\n"
    "direction = 30.0\ncourse = -20.0\nviscosity = 1e-3\n[grid]\nn_theta = 32\n";

/// The coarse navier-stokes case of test_ns_run.cpp (a = 0.5 m, U = 1 m/s; well under a second).
std::string ns_case(double Re, double alpha, double t_end) {
  return fmt::format(
      "title = \"test\"\n[model]\nflow = \"navier-stokes\"\n[cylinder]\nradius = 0.5\nspin_ratio = {}\n"
      "[flow]\nspeed = 1.0\ndensity = 1.0\nreynolds = {}\n[domain]\nouter_radius = 40.0\n[grid]\n"
      "n_theta = 48\n[time]\nend = {}\n",
      alpha, Re, t_end);
}

std::string write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

/// Every number is the "value" of an object that also has a "units" string (itself, or each element of an
/// array held there). Returns the JSON pointers of offenders.
void check_units(const json& j, const std::string& at, bool in_value, std::vector<std::string>& bad) {
  if (j.is_number()) {
    if (!in_value) bad.push_back(at);
    return;
  }
  if (j.is_array()) {
    for (size_t k = 0; k < j.size(); ++k) check_units(j[k], at + "/" + std::to_string(k), in_value, bad);
    return;
  }
  if (!j.is_object()) return;
  const bool quantity = j.contains("value") && j.contains("units") && j["units"].is_string();
  if (j.contains("value") && !quantity) bad.push_back(at + " (value without units)");
  for (auto it = j.begin(); it != j.end(); ++it)
    check_units(it.value(), at + "/" + it.key(), quantity && it.key() == "value", bad);
}

json parse_checked(const std::string& text) {
  json j;
  REQUIRE_NOTHROW(j = json::parse(text));
  REQUIRE(j.is_object());
  std::vector<std::string> bad;
  check_units(j, "", false, bad);
  INFO("numbers without units: " << fmt::format("{}", fmt::join(bad, ", ")));
  CHECK(bad.empty());
  return j;
}

/// The label of each summary line (its first 15 columns, trimmed); a continuation line (empty label) is
/// "LABEL+" of the line above it, and the first line after a blank one with an empty label is "<head>".
std::vector<std::string> summary_labels(const std::string& text) {
  std::vector<std::string> labels;
  std::istringstream in(text);
  std::string line, previous = "<head>";
  bool first = true;
  while (std::getline(in, line)) {
    if (first) {  // "magnus VERSION — title"
      labels.push_back("<title>");
      first = false;
      continue;
    }
    if (line.empty()) {
      previous = "<head>";
      continue;
    }
    // The label column is 15 display columns: up to the first run of two spaces.
    std::string label = line.substr(0, line.find("  "));
    if (line.compare(0, 15, std::string(15, ' ')) == 0 || line[0] == ' ') label.clear();
    if (label.empty()) {
      labels.push_back(previous == "<head>" ? "<head>" : previous + "+");
    } else {
      labels.push_back(label);
      previous = label;
    }
  }
  return labels;
}

/// Each label of the summaries → the JSON pointers of its figures.
const std::map<std::string, std::vector<std::string>> kSummaryToJson = {
    // both models
    {"<title>", {"/software_version", "/title"}},
    {"case",
     {"/parameters/radius", "/parameters/spin", "/parameters/rpm", "/parameters/speed", "/parameters/spin_ratio",
      "/parameters/density"}},
    {"direction", {"/parameters/direction"}},
    {"direction+", {"/parameters/direction"}},  // the world's F_x, F_y: lift and drag turned by it
    {"course", {"/parameters/course", "/forces/thrust", "/forces/side_force"}},
    {"span",
     {"/parameters/span", "/forces/lift_total", "/forces/drag_total", "/forces/thrust_total",
      "/forces/side_force_total"}},
    {"span+", {"/forces/torque_total", "/forces/spin_power_total"}},
    {"grid",
     {"/parameters/n_theta", "/parameters/n_r", "/derived/nodes", "/parameters/spacing",
      "/parameters/outer_radius", "/parameters/outer_radius_requested"}},
    {"lift", {"/forces/lift_kutta_joukowski"}},
    {"drag", {"/forces"}},
    {"C_L", {"/forces/cl_seed_estimate"}},
    {"C_D", {"/forces"}},
    {"Magnus S", {"/forces/magnus_S", "/forces/magnus_S_exact"}},
    {"output", {"/output/file", "/output/xdmf"}},
    // potential flow
    {"circulation", {"/parameters/circulation", "/parameters/circulation_model"}},
    {"grid+", {}},  // the tolerance search's choice (potential) or the wall resolution (navier-stokes)
    {"solver", {"/parameters/method", "/parameters/stencil", "/derived/threads"}},
    {"timing",
     {"/timing/assemble_s", "/timing/factor_s", "/timing/solve_s", "/timing/postproc_s", "/timing/total_s"}},
    {"C_L+", {"/derived/cl_over_kj_minus_1", "/derived/kj_over_seed"}},
    {"ΔP top−bottom",
     {"/forces/delta_p_top_bottom", "/forces/delta_p_top_bottom_exact", "/forces/delta_p_seed_estimate"}},
    {"ΔP top−bottom+", {"/derived/delta_p_over_seed"}},
    {"stagnation", {"/stagnation/numeric"}},
    {"stagnation+", {"/stagnation/exact"}},
    {"errors",
     {"/errors/psi_max_rel", "/errors/cp_surface_max_abs", "/errors/cl_rel", "/errors/circulation_rel"}},
    {"errors+", {"/errors/cl_rel_estimated"}},
    {"Reynolds", {"/derived/reynolds", "/derived/viscosity"}},
    {"ideal", {"/derived/inviscid_upper_bound"}},
    {"ideal+", {"/derived/reference"}},
    {"rotor data", {"/derived/rotor_data"}},
    {"rotor data+", {"/derived/rotor_data"}},
    // navier-stokes
    {"case+", {"/parameters/viscosity", "/parameters/reynolds"}},
    {"model", {"/model"}},
    {"<head>", {"/model"}},  // the column heads "viscous (this run)", "ideal (potential flow …)"
    {"run",
     {"/timing/t_reached", "/derived/t_convective", "/timing/steps", "/timing/dt", "/derived/dt_convective",
      "/timing/total_s", "/derived/steps_per_second"}},
    {"run+", {"/status", "/partial", "/timing/newton_s", "/timing/stability_s", "/timing/march_s"}},
    {"verdict", {"/derived/wall_cells_unresolved", "/derived/wall_cells"}},
    {"C_D+", {"/forces/cd_pressure", "/forces/cd_friction"}},
    {"St = fD/U", {"/forces/strouhal", "/status"}},
    {"S/(2πρa²)", {"/forces/magnus_ratio", "/parameters/reynolds", "/parameters/spin_ratio"}},
    {"C_L, C_D", {"/forces/cl", "/forces/cd"}},
    {"forces", {"/forces/lift", "/forces/drag"}},
    {"torque", {"/forces/torque_mean", "/forces/spin_power_mean"}},
    {"torque+", {"/derived/torque_potential_vortex", "/derived/torque_over_potential_vortex_minus_1"}},
    {"separation", {"/separation"}},
    {"recirculation", {"/forces/recirculation_length"}},
    {"note", {"/derived/viscous_length_beyond_grid"}},
    {"3D", {"/derived/onset3d_verdict"}},
    {"stability", {"/forces/eigenvalue_real", "/forces/eigenvalue_imag", "/forces/eigenvalue_residual"}},
    {"grid study", {"/derived/steady_study/levels"}},
    {"grid study+", {"/derived/steady_study/levels"}},
    {"Richardson", {"/derived/steady_study/cd"}},
    {"Richardson+", {"/derived/steady_study/cl", "/derived/steady_study/recirculation_length"}},
    {"error (est.)", {"/errors/estimate_method"}},
    {"error (est.)+", {"/errors/means_converged"}},
};

/// Model-specific figures of labels both summaries share.
const std::map<std::string, std::vector<std::string>> kPotentialOnly = {
    {"lift", {"/forces/lift"}},
    {"drag", {"/forces/drag"}},
    {"C_L", {"/forces/cl", "/forces/cl_kutta_joukowski"}},
    {"C_D", {"/forces/cd"}},
    {"grid", {"/parameters/far_field"}},
    {"grid+", {"/derived/grid_choice"}},
};
const std::map<std::string, std::vector<std::string>> kViscousOnly = {
    {"lift", {"/forces/lift_mean"}},
    {"drag", {"/forces/drag_mean"}},
    {"C_L", {"/forces/cl_mean", "/forces/cl_amplitude", "/forces/cl_ideal"}},
    {"C_D", {"/forces/cd_mean"}},
    {"grid+", {"/derived/wall_cells"}},
};

/// Every label of the summary is mapped, and every mapped figure is in the JSON (a quantity, a text or a
/// yes/no).
void check_counterparts(const std::string& summary, const json& j, bool viscous) {
  const auto labels = summary_labels(summary);
  REQUIRE(labels.size() > 8);
  for (const auto& label : labels) {
    INFO("summary label '" << label << "'");
    const auto it = kSummaryToJson.find(label);
    REQUIRE(it != kSummaryToJson.end());
    std::vector<std::string> pointers = it->second;
    const auto& extra = viscous ? kViscousOnly : kPotentialOnly;
    if (const auto e = extra.find(label); e != extra.end())
      pointers.insert(pointers.end(), e->second.begin(), e->second.end());
    for (const auto& p : pointers) {
      INFO("JSON pointer " << p);
      REQUIRE(j.contains(json::json_pointer(p)));
      const json& v = j[json::json_pointer(p)];
      const bool ok = v.is_string() || v.is_boolean() ||
                      (v.is_object() && (v.contains("units") || !v.empty())) || v.is_array();
      CHECK(ok);
    }
  }
}

/// `magnus run CASE` for its summary, then the same with --json: both succeed, the JSON alone on stdout
/// and nothing on stderr, and every label of the summary has its figures in the JSON.
json run_beside_summary(const std::string& c, const std::string& dir, const std::vector<std::string>& extra,
                        bool viscous) {
  std::vector<std::string> args = {"run", c, "-o", dir + "/r.h5"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto text = test::magnus_cmd(args, dir);
  INFO(text.err);
  REQUIRE(text.status == 0);
  args.push_back("--json");
  const auto o = test::magnus_cmd(args, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  REQUIRE(o.err.empty());
  const json j = parse_checked(o.out);
  check_counterparts(text.out, j, viscous);
  return j;
}

}  // namespace

TEST_CASE("run --json, potential flow: every figure of the summary with its units", "[app][json]") {
  const std::string dir = test::temp_dir("json-run");
  const std::string c = write(dir + "/case.toml", kPotentialCase);
  const json j = run_beside_summary(c, dir, {}, false);
  CHECK(j["model"] == "potential");
  CHECK(j["forces"]["cl"]["units"] == "1");
  CHECK(j["forces"]["lift"]["units"] == "N/m");
  CHECK(j["forces"]["cl"]["value"].get<double>() == Approx(-2.0 * M_PI).epsilon(1e-2));
  CHECK(j["stagnation"]["exact"].size() == 2);
  CHECK_FALSE(j.contains("separation"));
  CHECK_FALSE(j["forces"].contains("cl_mean"));  // the other model's figures are absent, not null
}

TEST_CASE("run --json, no flow: undefined coefficients are null", "[app][json]") {
  const std::string dir = test::temp_dir("json-run-u0");
  const std::string c =
      write(dir + "/case.toml",
            "[cylinder]\nradius = 0.1\nspin = 50.0\n[flow]\nspeed = 0.0\n[grid]\nn_theta = 16\n");
  const json j = run_beside_summary(c, dir, {}, false);
  CHECK(j["forces"]["cl"]["value"].is_null());
  CHECK(j["forces"]["cl"]["units"] == "1");
  CHECK(j["parameters"]["spin_ratio"]["value"].is_null());
}

TEST_CASE("run --json, navier-stokes: the means, St, S/(2πρa²), the ideal, status", "[app][json][ns]") {
  const std::string dir = test::temp_dir("json-run-ns");
  const std::string c = write(dir + "/case.toml", ns_case(100, 1, 4));
  const json j = run_beside_summary(c, dir, {}, true);
  CHECK(j["model"] == "navier-stokes");
  CHECK(j["partial"] == false);
  CHECK(j["status"].is_string());
  for (const char* k : {"cl_mean", "cd_mean", "strouhal", "magnus_ratio", "cl_ideal", "cl_amplitude"})
    CHECK(j["forces"].contains(k));
  CHECK(j["forces"]["cl_ideal"]["value"].get<double>() == Approx(-2.0 * M_PI).epsilon(1e-12));
  CHECK(
      j["forces"]["magnus_ratio"]["value"].get<double>() ==
      Approx(j["forces"]["cl_mean"]["value"].get<double>() / j["forces"]["cl_ideal"]["value"].get<double>()));
  // The run's own error estimate (a companion on the grid twice as coarse): /errors, relative, positive.
  for (const char* k : {"cl_mean_rel_estimate", "cd_mean_rel_estimate"}) {
    INFO(k);
    REQUIRE(j["errors"].contains(k));
    CHECK(j["errors"][k]["units"] == "1");
    CHECK(j["errors"][k]["value"].get<double>() > 0.0);
  }
  CHECK(j["errors"]["strouhal_rel_estimate"]["value"].is_null());  // no period by t = 4 D/U: undefined
  CHECK(j["errors"]["means_converged"]["value"].get<double>() == 0.0);  // time.end 4: far from converged
  CHECK(j["separation"]["units"] == "rad");
}

TEST_CASE("run --json, navier-stokes steady and auto: the grid study and the eigenvalue", "[app][json][ns]") {
  const std::string dir = test::temp_dir("json-run-ns-steady");
  for (const char* mode : {"steady", "auto"}) {
    INFO("time.mode = " << mode);
    // Re 20 for the grid study; Re 60, α 3 for "auto", which tests the stability there (at Re 20 it knows).
    const std::string c =
        write(dir + "/case.toml", std::string(mode) == "steady" ? ns_case(20, 0.5, 4) : ns_case(60, 3, 4));
    const json j = run_beside_summary(c, dir, {"--set", std::string("time.mode=") + mode}, true);
    if (std::string(mode) == "steady") {
      REQUIRE(j["derived"]["steady_study"]["levels"].size() >= 2);
      const auto& cd = j["derived"]["steady_study"]["cd"];
      CHECK(cd["error"]["value"].get<double>() > 0.0);
      CHECK(std::fabs(cd["value"].get<double>() - cd["finest"]["value"].get<double>()) <
            0.05 * cd["finest"]["value"].get<double>());
      // The file holds the same study: each grid's C_D and the Richardson value with its error bar.
      const auto o = test::magnus_cmd({"inspect", dir + "/r.h5", "--json"}, dir);
      INFO(o.err);
      REQUIRE(o.status == 0);
      const json f = parse_checked(o.out);
      const auto& levels = j["derived"]["steady_study"]["levels"];
      REQUIRE(f["steady_study"]["levels"]["cd"]["value"].size() == levels.size());
      for (size_t k = 0; k < levels.size(); ++k) {
        CHECK(f["steady_study"]["levels"]["cd"]["value"][k].get<double>() == levels[k]["cd"]["value"].get<double>());
        CHECK(f["steady_study"]["levels"]["n_theta"]["value"][k].get<double>() == levels[k]["n_theta"]["value"].get<double>());
      }
      CHECK(f["steady_study"]["cd"]["value"].get<double>() == cd["value"].get<double>());
      CHECK(f["steady_study"]["cd_error"]["value"].get<double>() == cd["error"]["value"].get<double>());
      CHECK(f["steady_study"]["cd"]["units"] == "1");
    } else {  // Re 60, α 3: a stable steady state, and its leading eigenvalue decays; no grid study stored
      CHECK(j["forces"]["eigenvalue_real"]["value"].get<double>() < 0.0);
      // Its evidence: the eigenvector's relative residual, below the search's tolerance.
      CHECK(j["forces"]["eigenvalue_residual"]["value"].get<double>() <= StabilityOptions{}.tol);
      // What took the time: Newton and the eigenvalue test, each named; no march.
      CHECK(j["timing"]["newton_s"]["value"].get<double>() > 0.0);
      CHECK(j["timing"]["stability_s"]["value"].get<double>() > 0.0);
      CHECK(j["timing"]["march_s"]["value"].is_null());
      CHECK(j["timing"]["newton_s"]["units"] == "s");
      const auto o = test::magnus_cmd({"inspect", dir + "/r.h5", "--json"}, dir);
      REQUIRE(o.status == 0);
      CHECK_FALSE(parse_checked(o.out).contains("steady_study"));
    }
  }
}

TEST_CASE("json output: errors stay one line on stderr, nothing on stdout", "[app][json]") {
  const std::string dir = test::temp_dir("json-errors");
  const std::string c = write(dir + "/case.toml", "[cylinder]\nradius = 0.1\n[flow]\nspeed = 10.0\n");
  for (const auto& args : {std::vector<std::string>{"run", c, "-o", dir + "/r.h5", "--json"},
                           std::vector<std::string>{"inspect", dir + "/none.h5", "--json"},
                           std::vector<std::string>{"compare", dir + "/none.h5", "--json"},
                           std::vector<std::string>{"run", c, "--json", "-q"}}) {
    const auto o = test::magnus_cmd(args, dir);
    INFO(args[0] << ": " << o.err);
    CHECK(o.status != 0);
    CHECK(o.out.empty());
    CHECK(test::lines(o.err) == 1);
  }
}

TEST_CASE("sweep --json: one object per point, each figure with units", "[app][json]") {
  const std::string dir = test::temp_dir("json-sweep");
  const std::string c = write(dir + "/case.toml", kPotentialCase);
  const auto o = test::magnus_cmd({"sweep", c, "--spin-ratio", "0:2:0.5", "--json"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  const json j = parse_checked(o.out);
  REQUIRE(j["points"].size() == 5);
  for (const char* k : {"alpha", "circulation", "lift", "drag", "cl", "cl_kutta_joukowski",
                        "cl_seed_estimate", "cl_over_kj_minus_1", "kj_over_seed", "cd", "delta_p_top_bottom",
                        "delta_p_seed_estimate", "stagnation"})
    CHECK(j["points"][1].contains(k));
  CHECK(j["points"][0]["kj_over_seed"]["value"].is_null());  // α = 0: the seed estimate is 0
  CHECK(j["points"][2]["cl_kutta_joukowski"]["value"].get<double>() == Approx(-2.0 * M_PI));
  CHECK(j["timing"]["linear_solves"]["value"] == 2);
  const auto both = test::magnus_cmd({"sweep", c, "--spin-ratio", "0:2:0.5", "--json", "--csv", "-"}, dir);
  CHECK(both.status != 0);
  CHECK(test::lines(both.err) == 1);
}

TEST_CASE("compare --json and inspect --json: the stored figures with units", "[app][json]") {
  const std::string dir = test::temp_dir("json-files");
  const std::string c = write(dir + "/case.toml", kPotentialCase);
  REQUIRE(test::magnus_cmd({"run", c, "-o", dir + "/a.h5"}, dir).status == 0);
  REQUIRE(test::magnus_cmd({"run", c, "-o", dir + "/b.h5", "--set", "cylinder.spin_ratio=2"}, dir).status ==
          0);
  REQUIRE(test::magnus_cmd({"sweep", c, "--spin-ratio", "0:4:1", "-o", dir + "/s.h5"}, dir).status == 0);

  const auto cmp =
      test::magnus_cmd({"compare", dir + "/a.h5", dir + "/b.h5", "--json", "--csv", dir + "/c.csv"}, dir);
  INFO(cmp.err);
  REQUIRE(cmp.status == 0);
  const json jc = parse_checked(cmp.out);
  REQUIRE(jc["files"].size() == 2);
  CHECK(std::find(jc["differing"].begin(), jc["differing"].end(), "spin") != jc["differing"].end());
  CHECK(jc["files"][1]["forces"]["cl"]["value"].get<double>() == Approx(-4.0 * M_PI).epsilon(1e-2));
  CHECK(jc["files"][0]["derived"].contains("kj_over_seed"));
  CHECK(test::lines(test::slurp(dir + "/c.csv")) == 3);

  const auto ins = test::magnus_cmd({"inspect", dir + "/a.h5", "--json"}, dir);
  INFO(ins.err);
  REQUIRE(ins.status == 0);
  const json ji = parse_checked(ins.out);
  CHECK(ji["format"] == "magnus-flow");
  CHECK(ji["parameters"]["radius"]["units"] == "m");
  CHECK(ji["stagnation"]["numeric"].size() == 2);
  CHECK(ji["datasets"].size() > 10);

  const auto sw = test::magnus_cmd({"inspect", dir + "/s.h5", "--json"}, dir);
  INFO(sw.err);
  REQUIRE(sw.status == 0);
  const json js = parse_checked(sw.out);
  CHECK(js["format"] == "magnus-sweep");
  CHECK(js["columns"]["cl"]["value"].size() == 5);
  CHECK(js["columns"]["kj_over_seed"]["value"][0].is_null());  // the fill value, read as undefined
}

TEST_CASE("inspect --surface-csv: θ in rad and degrees, u_θ, p, Cp (and τ_w for navier-stokes)",
          "[app][json]") {
  const std::string dir = test::temp_dir("surface-csv");
  REQUIRE(
      test::magnus_cmd({"run", write(dir + "/case.toml", kPotentialCase), "-o", dir + "/a.h5"}, dir).status ==
      0);
  const auto o = test::magnus_cmd({"inspect", dir + "/a.h5", "--surface-csv", dir + "/s.csv"}, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.find("magnus-flow version 2") != std::string::npos);  // the text is still printed
  const std::string csv = test::slurp(dir + "/s.csv");
  CHECK(csv.rfind("theta_rad,theta_deg,u_theta_m_s,pressure_Pa,cp\n", 0) == 0);
  CHECK(test::lines(csv) == 33);
  // Row j = 8 of 32 is θ = π/2, 90°: u_θ ≈ U(α − 2) = −10 m/s.
  std::istringstream in(csv);
  std::string line;
  for (int k = 0; k <= 9; ++k) std::getline(in, line);
  double th, deg, u, p, cp;
  REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf", &th, &deg, &u, &p, &cp) == 5);
  CHECK(th == Approx(M_PI / 2));
  CHECK(deg == Approx(90.0));
  CHECK(u == Approx(-10.0).epsilon(0.05));
  CHECK(cp == Approx(0.0).margin(0.1));  // 1 − (u/U)² at u = −U

  const auto out = test::magnus_cmd({"inspect", dir + "/a.h5", "--surface-csv", "-"}, dir);
  REQUIRE(out.status == 0);
  CHECK(out.out == csv);  // stdout is the CSV alone

  const std::string ns = write(dir + "/ns.toml", ns_case(100, 1, 1));
  REQUIRE(test::magnus_cmd({"run", ns, "-o", dir + "/n.h5"}, dir).status == 0);
  const auto v = test::magnus_cmd({"inspect", dir + "/n.h5", "--surface-csv", "-"}, dir);
  INFO(v.err);
  REQUIRE(v.status == 0);
  CHECK(v.out.rfind("theta_rad,theta_deg,u_theta_m_s,pressure_Pa,cp,tau_w_Pa\n", 0) == 0);
  CHECK(test::lines(v.out) == 49);

  const auto bad = test::magnus_cmd({"inspect", dir + "/a.h5", "--surface-csv", dir}, dir);  // a directory
  CHECK(bad.status != 0);
  CHECK(test::lines(bad.err) == 1);
}
