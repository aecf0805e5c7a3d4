// magnus probe: the interpolation to its order (against the exact potential flow sampled on the nodes), the
// probed values of real results converging at the scheme's order, the outputs and the errors.
#include <fmt/core.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "physics/exact.hpp"
#include "postproc/probe.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// 120 points off the nodes, scattered (a fixed pseudo-random sequence) over r = 1.02a … 4a and every angle
/// (a = 0.1 m): the maximum error over many points measures the interpolation's order, not the luck of
/// where a few points fall between the nodes.
std::vector<std::pair<double, double>> scattered_points() {
  std::vector<std::pair<double, double>> pts;
  unsigned long s = 12345;
  auto next = [&s] {
    s = (s * 6364136223846793005UL + 1442695040888963407UL);
    return double(s >> 11) / double(1UL << 53);
  };
  for (int k = 0; k < 120; ++k) {
    const double r = 0.1 * 1.02 * std::pow(4.0 / 1.02, next()), t = 2.0 * M_PI * next();
    pts.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return pts;
}
const std::vector<std::pair<double, double>> kPoints = scattered_points();

ExactFlow exact() {
  ExactFlow e;
  e.a = 0.1;
  e.U = 10.0;
  e.Gamma = 2.0 * M_PI * 0.1 * 0.1 * 100.0;  // α = 1
  return e;
}

double exact_u_x(const ExactFlow& e, double x, double y) {
  const double r = std::hypot(x, y), t = std::atan2(y, x);
  return e.u_r(r, t) * std::cos(t) - e.u_theta(r, t) * std::sin(t);
}

double exact_u_y(const ExactFlow& e, double x, double y) {
  const double r = std::hypot(x, y), t = std::atan2(y, x);
  return e.u_r(r, t) * std::sin(t) + e.u_theta(r, t) * std::cos(t);
}

/// Max error of interpolating the exact u_x sampled on an n_θ log-polar grid (square cells, R = 20a).
double interpolation_error(int n_theta, int points) {
  const ExactFlow e = exact();
  const int n_r = default_n_r(Spacing::geometric, 20.0, n_theta);
  const PolarGrid g = make_grid(e.a, 20.0, n_r, n_theta, Spacing::geometric);
  std::vector<double> f(size_t(g.nodes()));
  for (int i = 0; i < g.n_r; ++i)
    for (int j = 0; j < g.n_theta; ++j)
      f[size_t(i) * size_t(n_theta) + size_t(j)] =
          exact_u_x(e, g.r[i] * std::cos(g.theta[j]), g.r[i] * std::sin(g.theta[j]));
  double err = 0.0;
  for (const auto& [x, y] : kPoints) {
    const ProbeStencil s = probe_stencil(g, x, y, points);
    err = std::max(err, std::fabs(probe_value(s, f, n_theta) - exact_u_x(e, x, y)));
  }
  return err;
}

/// Probe the result of the α = 1 case on an n_θ grid at kPoints (CSV on stdout); max errors of u (m/s)
/// and p (Pa) against the exact flow.
std::pair<double, double> probed_errors(const std::string& dir, int n_theta) {
  const std::string c = dir + "/case.toml";
  std::ofstream(c) << fmt::format(
      "[cylinder]\nradius = 0.1\nspin_ratio = 1.0\n[flow]\nspeed = 10.0\ndensity = 1.0\n[grid]\nn_theta = "
      "{}\n",
      n_theta);
  const std::string out = dir + fmt::format("/r{}.h5", n_theta);
  REQUIRE(test::magnus_cmd({"run", c, "-o", out, "-q"}, dir).status == 0);
  std::vector<std::string> args = {"probe", out, "--csv", "-", "--"};
  for (const auto& [x, y] : kPoints) args.push_back(fmt::format("{:.17g},{:.17g}", x, y));
  const auto o = test::magnus_cmd(args, dir);
  INFO(o.err);
  REQUIRE(o.status == 0);
  std::istringstream in(o.out);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "x_m,y_m,r_m,theta_rad,u_x_m_s,u_y_m_s,pressure_Pa,cp");
  const ExactFlow e = exact();
  double eu = 0.0, ep = 0.0;
  size_t n = 0;
  while (std::getline(in, line)) {
    double x, y, r, t, ux, uy, p, cp;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &x, &y, &r, &t, &ux, &uy, &p, &cp) ==
            8);
    eu = std::max({eu, std::fabs(ux - exact_u_x(e, x, y)), std::fabs(uy - exact_u_y(e, x, y))});
    const double cp_exact = e.cp(r, t);
    ep = std::max(ep, std::fabs(p - 0.5 * 1.0 * 100.0 * cp_exact));  // p∞ = 0, ½ρU² = 50 Pa
    CHECK(cp == Approx(p / 50.0).margin(1e-12));
    ++n;
  }
  REQUIRE(n == kPoints.size());
  return {eu, ep};
}

}  // namespace

TEST_CASE("probe interpolation: 4 points are 4th order, 6 points 6th order, off the nodes",
          "[postproc][probe]") {
  // Between n_θ = 256 and 1024 (h / 4): coarser grids are not yet asymptotic for the 6-point formula.
  for (const int points : {4, 6}) {
    const double coarse = interpolation_error(256, points), fine = interpolation_error(1024, points);
    INFO(points << " points: errors " << coarse << ", " << fine);
    CHECK(test::observed_order(coarse, fine, 4.0) == Approx(double(points)).margin(0.3));
  }
  // On a node the interpolation returns the node's value.
  const PolarGrid g = make_grid(0.1, 20.0, 40, 32, Spacing::geometric);
  const ProbeStencil s = probe_stencil(g, g.r[5] * std::cos(g.theta[3]), g.r[5] * std::sin(g.theta[3]), 4);
  std::vector<double> f(size_t(g.nodes()), 0.0);
  f[5 * 32 + 3] = 1.0;
  CHECK(probe_value(s, f, 32) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("magnus probe: values of a 5-point result converge at 2nd order to the exact flow",
          "[app][probe]") {
  const std::string dir = test::temp_dir("probe-order");
  const auto [u1, p1] = probed_errors(dir, 128);
  const auto [u2, p2] = probed_errors(dir, 256);
  const auto [u3, p3] = probed_errors(dir, 512);
  INFO("u errors " << u1 << " " << u2 << " " << u3 << "; p errors " << p1 << " " << p2 << " " << p3);
  CHECK(test::observed_order(u1, u2) == Approx(2.0).margin(0.3));
  CHECK(test::observed_order(u2, u3) == Approx(2.0).margin(0.3));
  CHECK(test::observed_order(p1, p2) == Approx(2.0).margin(0.3));
  CHECK(test::observed_order(p2, p3) == Approx(2.0).margin(0.3));
}

TEST_CASE("magnus probe: table, JSON, a point outside the grid, a malformed point", "[app][probe]") {
  const std::string dir = test::temp_dir("probe-cli");
  std::ofstream(dir + "/case.toml")
      << "[cylinder]\nradius = 0.1\nspin_ratio = 1.0\n[flow]\nspeed = 10.0\n[grid]\nn_theta = 32\n";
  REQUIRE(test::magnus_cmd({"run", dir + "/case.toml", "-o", dir + "/r.h5", "-q"}, dir).status == 0);
  const auto t = test::magnus_cmd({"probe", dir + "/r.h5", "0.2,0.1", "0,0.15"}, dir);
  INFO(t.err);
  REQUIRE(t.status == 0);
  CHECK(t.out.find("u_x (m/s)") != std::string::npos);
  CHECK(test::lines(t.out) == 6);

  const auto j = test::magnus_cmd({"probe", dir + "/r.h5", "--json", "--", "-0.2,0.1"}, dir);
  INFO(j.err);
  REQUIRE(j.status == 0);
  const auto doc = nlohmann::json::parse(j.out);
  REQUIRE(doc["points"].size() == 1);
  CHECK(doc["points"][0]["u_x"]["units"] == "m/s");
  CHECK(doc["points"][0]["x"]["value"].get<double>() == Approx(-0.2));
  CHECK(doc["field_order"]["value"] == 2);

  for (const auto& [point, named] : {std::pair{"0.05,0.02", "(0.05, 0.02)"}, std::pair{"30,0", "(30, 0)"}}) {
    const auto o = test::magnus_cmd({"probe", dir + "/r.h5", "0.2,0.1", point}, dir);
    CHECK(o.status != 0);
    CHECK(o.out.empty());
    CHECK(test::lines(o.err) == 1);
    CHECK(o.err.find(named) != std::string::npos);
    CHECK(o.err.find("outside the grid") != std::string::npos);
  }
  for (const char* bad : {"0.2", "0.2,x", "0.2,0.1,0.3", "nan,0.2"}) {
    const auto o = test::magnus_cmd({"probe", dir + "/r.h5", bad}, dir);
    INFO(bad << ": " << o.err);
    CHECK(o.status != 0);
    CHECK(test::lines(o.err) == 1);
    CHECK(o.err.find(bad) != std::string::npos);
  }
}
