// `magnus compare` with navier-stokes results: the viscous rows beside the ideal ones, "—" where a row is
// not of a file's model, mixed comparisons in the table and the CSV.
#include <fmt/core.h>
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "app/compare.hpp"
#include "io/hdf5_io.hpp"
#include "io/viscous_fixture.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

/// The cells of the table row that starts with label (after the two-space indent), split on spaces.
std::vector<std::string> table_row(const std::string& table, const std::string& label) {
  std::istringstream in(table);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("  " + label + " ", 0) == 0) {
      std::istringstream cells(line.substr(2 + label.size()));
      std::vector<std::string> out;
      std::string c;
      while (cells >> c) out.push_back(c);
      return out;
    }
  return {};
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(s);
  while (std::getline(in, cell, ',')) out.push_back(cell);
  if (!s.empty() && s.back() == ',') out.push_back("");
  return out;
}

}  // namespace

TEST_CASE("compare: viscous and ideal side by side, '—' where a row is not of the file's model",
          "[app][compare][viscous]") {
  const std::string dir = test::temp_dir("compare-ns");
  Case c = test::make_case(1.0, 32);
  c.title = "potential";
  write_result(run_case(c), dir + "/pot.h5");
  const FlowResult ns = test::viscous_result_by_hand(1.0, 32, 16, 2);
  write_result(ns, dir + "/ns.h5");
  FlowResult ns0 = test::viscous_result_by_hand(0.0, 32, 16, 0);  // α = 0: S/(2πρa²) undefined
  write_result(ns0, dir + "/ns0.h5");

  const Comparison m = compare_results({dir + "/pot.h5", dir + "/ns.h5", dir + "/ns0.h5"});
  CAPTURE(m.table);
  const auto& v = *ns.viscous;
  CHECK(table_row(m.table, "C_L mean (viscous)") ==
        std::vector<std::string>{"—", fmt::format("{:.6g}", *v.cl_mean), "0"});
  CHECK(table_row(m.table, "C_D mean (viscous)")[0] == "—");
  CHECK(table_row(m.table, "C_L amplitude").at(1) == fmt::format("{:.4g}", *v.cl_amplitude));
  CHECK(table_row(m.table, "Strouhal number").at(1) == fmt::format("{:.5g}", *v.strouhal));
  CHECK(table_row(m.table, "C_L ideal (potential)").at(1) == fmt::format("{:.6g}", *v.cl_ideal));
  CHECK(table_row(m.table, "S/(2πρa²)") ==
        std::vector<std::string>{"—", fmt::format("{:.4f}", *v.magnus_ratio), "undefined"});
  // Potential flow's errors are not the viscous files'.
  const auto err = table_row(m.table, "error C_L rel");
  REQUIRE(err.size() == 3);
  CHECK(err[0] != "—");
  CHECK(err[1] == "—");
  CHECK(err[2] == "—");
  // The model differs: a parameter row.
  CHECK(table_row(m.table, "model") ==
        std::vector<std::string>{"potential", "navier-stokes", "navier-stokes"});
  CHECK(std::find(m.differing.begin(), m.differing.end(), "model") != m.differing.end());

  // CSV: the viscous columns, empty for the potential file; full precision for the viscous ones.
  std::istringstream csv(m.csv);
  std::string line;
  std::getline(csv, line);
  const auto head = split(line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(split(line));
  REQUIRE(rows.size() == 3);
  auto col = [&](const std::string& name) {
    const auto it = std::find(head.begin(), head.end(), name);
    REQUIRE(it != head.end());
    return size_t(it - head.begin());
  };
  for (const auto& r : rows) REQUIRE(r.size() == head.size());
  CHECK(rows[0][col("cl_mean")].empty());
  CHECK(std::stod(rows[1][col("cl_mean")]) == *v.cl_mean);
  CHECK(std::stod(rows[1][col("magnus_ratio")]) == *v.magnus_ratio);
  CHECK(rows[2][col("magnus_ratio")].empty());
  CHECK(rows[1][col("cl_rel")].empty());
  CHECK(rows[1][col("model")] == "navier-stokes");
}

TEST_CASE("compare: rows of a model no file has are left out", "[app][compare][viscous]") {
  const std::string dir = test::temp_dir("compare-ns-only");
  Case c = test::make_case(1.0, 32);
  write_result(run_case(c), dir + "/a.h5");
  c.grid.n_theta = 64;
  write_result(run_case(c), dir + "/b.h5");
  const Comparison pot = compare_results({dir + "/a.h5", dir + "/b.h5"});
  CHECK(pot.table.find("C_L mean") == std::string::npos);
  CHECK(pot.csv.find("cl_mean") == std::string::npos);
  for (const char* row : {"C_L numeric", "error C_L rel", "C_D"})
    for (const auto& cell : table_row(pot.table, row)) CHECK(cell != "—");
  CHECK(pot.table.find("\n  model") == std::string::npos);

  write_result(test::viscous_result_by_hand(1.0), dir + "/n1.h5");
  write_result(test::viscous_result_by_hand(1.5), dir + "/n2.h5");
  const Comparison vis = compare_results({dir + "/n1.h5", dir + "/n2.h5"});
  CAPTURE(vis.table);
  CHECK(vis.table.find("error C_L rel") == std::string::npos);
  CHECK(vis.csv.find("cl_rel") == std::string::npos);
  CHECK(table_row(vis.table, "C_L mean (viscous)").size() == 2);
  CHECK(table_row(vis.table, "C_L ideal (potential)").size() == 2);
}

TEST_CASE("compare: a navier-stokes file's lift, drag, C_L, C_D are its means, last-step values say so",
          "[app][compare][viscous]") {
  const std::string dir = test::temp_dir("compare-ns-means");
  Case c = test::make_case(1.0, 32);
  write_result(run_case(c), dir + "/ideal.h5");
  FlowResult ns = test::viscous_result_by_hand(1.0, 32, 16, 0);
  const ViscousPart& v = *ns.viscous;
  // The last step is an instant of the shedding cycle, away from the mean.
  ns.forces.cl = v.last.C_L, ns.forces.cd = v.last.C_D;
  ns.forces.lift = 0.9 * v.lift_mean, ns.forces.drag = 1.2 * v.drag_mean;
  ns.forces.cl_kutta_joukowski = *v.cl_ideal;
  ns.forces.delta_p_top_bottom = 1.25;
  REQUIRE(std::fabs(*ns.forces.cl - *v.cl_mean) > 0.01);
  write_result(ns, dir + "/viscous.h5");
  const Comparison m = compare_results({dir + "/ideal.h5", dir + "/viscous.h5"});
  CAPTURE(m.table);
  CHECK(table_row(m.table, "C_L numeric").at(1) == fmt::format("{:.10g}", *v.cl_mean));
  CHECK(table_row(m.table, "C_D").at(1) == fmt::format("{:.3e}", *v.cd_mean));
  CHECK(table_row(m.table, "lift (N/m)").at(1) == fmt::format("{:.10g}", v.lift_mean));
  CHECK(table_row(m.table, "drag (N/m)").at(1) == fmt::format("{:.3g}", v.drag_mean));
  CHECK(table_row(m.table, "C_L numeric/K–J − 1").at(1) ==
        fmt::format("{:.3e}", *v.cl_mean / *v.cl_ideal - 1.0));
  // ΔP top−bottom is the last step's surface pressure: marked in the table and in the CSV.
  CHECK(table_row(m.table, "ΔP top−bottom (Pa)") ==
        std::vector<std::string>{table_row(m.table, "ΔP top−bottom (Pa)").at(0), "1.25", "(last", "step)"});
  std::istringstream csv(m.csv);
  std::string line;
  std::getline(csv, line);
  const auto head = split(line);
  REQUIRE(head.back() == "last_step");
  std::getline(csv, line);
  CHECK(split(line).back().empty());  // the potential file: no last-step values
  std::getline(csv, line);
  const auto row = split(line);
  CHECK(row.back() == "delta_p_top_bottom_Pa");
  const size_t cl = size_t(std::find(head.begin(), head.end(), "cl") - head.begin());
  REQUIRE(cl < row.size());
  CHECK(std::stod(row[cl]) == *v.cl_mean);
}
