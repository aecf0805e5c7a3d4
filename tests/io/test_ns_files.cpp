// A navier-stokes result in its file: the stored states (/snapshots) and the .xmf's time series of them,
// read back by read_result and shown by inspect; the potential flow's sidecar is untouched.
#include <fmt/core.h>
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "app/compare.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/ns_sweep_file.hpp"
#include "io/result_reader.hpp"
#include "io/schema.hpp"
#include "io/viscous_fixture.hpp"
#include "io/xdmf.hpp"
#include "support.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

bool validates(const std::string& xmf, const std::string& dir) {
  const std::string dtd = std::string(MAGNUS_SOURCE_DIR) + "/tests/data/Xdmf.dtd";
  if (!fs::exists(dir + "/Xdmf.dtd")) fs::copy_file(dtd, dir + "/Xdmf.dtd");  // the DOCTYPE names it
  const std::string cmd = "xmllint --noout --dtdvalid '" + dtd + "' '" + xmf + "' 2>'" + dir + "/lint.txt'";
  return std::system(cmd.c_str()) == 0 && test::slurp(dir + "/lint.txt").empty();
}

}  // namespace

TEST_CASE("navier-stokes: the stored states are in /snapshots with units, once, and read back",
          "[io][format][viscous]") {
  const std::string dir = test::temp_dir("ns-snapshots");
  const FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 4);
  write_result(r, dir + "/ns.h5");
  const ResultFile f(dir + "/ns.h5");
  std::vector<size_t> shape;
  const auto t = f.dataset("/snapshots/t", &shape);
  REQUIRE(shape == std::vector<size_t>{4});
  CHECK(t[3] == r.viscous->snapshots[3].t);
  CHECK(f.attr_string("/snapshots/t", "units") == "s");
  for (const char* p : {"/snapshots/psi", "/snapshots/vorticity"}) {
    CAPTURE(p);
    f.dataset(p, &shape);
    CHECK(shape == std::vector<size_t>{4, 16, 32});
    CHECK(f.attr_string(p, "units") == dataset_units(p));
    CHECK_FALSE(dataset_units(p).empty());
  }
  // Every dataset's unit is the schema's, the views of each state included.
  for (const auto& [path, sh] : f.datasets()) {
    CAPTURE(path);
    CHECK(f.attr_string(path, "units") == dataset_units(path));
  }
  CHECK(dataset_units("/mesh/snapshots/vorticity/3") == "1/s");
  // Stored once: the views of the states take no storage, the file is about the size of its values.
  CHECK(f.has("/mesh/snapshots/vorticity/3"));
  CHECK(f.dataset("/mesh/snapshots/vorticity/2") == r.viscous->snapshots[2].vorticity);
  CHECK(f.dataset("/mesh/snapshots/psi/0") == r.viscous->snapshots[0].psi);

  const FlowResult b = read_result(dir + "/ns.h5");
  REQUIRE(b.viscous);
  REQUIRE(b.viscous->snapshots.size() == 4);
  for (size_t k = 0; k < 4; ++k) {
    CHECK(b.viscous->snapshots[k].t == r.viscous->snapshots[k].t);
    CHECK(b.viscous->snapshots[k].psi == r.viscous->snapshots[k].psi);
    CHECK(b.viscous->snapshots[k].vorticity == r.viscous->snapshots[k].vorticity);
  }
  CHECK(b.viscous->history.size() == r.viscous->history.size());
  CHECK(b.fields.vorticity == r.fields.vorticity);
  CHECK(b.surface.shear_stress == r.surface.shear_stress);
}

TEST_CASE("navier-stokes: the .xmf adds a temporal collection of the states and still validates",
          "[io][format][xdmf][viscous]") {
  const std::string dir = test::temp_dir("ns-xdmf");
  const FlowResult r = test::viscous_result_by_hand(1.0, 16, 10, 3);
  write_result(r, dir + "/ns.h5");
  const std::string xmf = test::slurp(dir + "/ns.xmf");
  CHECK(count(xmf, "CollectionType=\"Temporal\"") == 1);
  CHECK(count(xmf, "<Time Value=") == 3);
  CHECK(count(xmf, "ns.h5:/mesh/snapshots/vorticity/") == 3);
  CHECK(count(xmf, "ns.h5:/mesh/snapshots/psi/") == 3);
  CHECK(count(xmf, "ns.h5:/mesh/quads") == 4);  // the states are on the grid's nodes and quadrilaterals
  // The last state's grid comes first, as for any result.
  CHECK(xmf.find("GridType=\"Uniform\"") < xmf.find("GridType=\"Collection\""));
  REQUIRE(validates(dir + "/ns.xmf", dir));

  // No states: no collection, no /snapshots.
  FlowResult none = r;
  none.viscous->snapshots.clear();
  write_result(none, dir + "/none.h5");
  CHECK(test::slurp(dir + "/none.xmf").find("Collection") == std::string::npos);
  CHECK_FALSE(ResultFile(dir + "/none.h5").has("/snapshots"));
  CHECK(read_result(dir + "/none.h5").viscous->snapshots.empty());
  REQUIRE(validates(dir + "/none.xmf", dir));
}

TEST_CASE("potential flow: the sidecar is the last state's grid alone, as before", "[io][format][xdmf]") {
  Case c = test::make_case(1.0, 16);
  c.output.fields.reset();
  const FlowResult r = run_case(c);
  const std::string x = xdmf_text(r, "p.h5");
  CHECK(x.find("Collection") == std::string::npos);
  CHECK(x.find("<Time") == std::string::npos);
  CHECK(count(x, "<Grid ") == 1);
}

TEST_CASE("inspect: a navier-stokes file's history length and stored states, with units",
          "[io][inspect][viscous]") {
  const std::string dir = test::temp_dir("ns-inspect");
  const FlowResult r = test::viscous_result_by_hand(1.0, 16, 10, 5);
  write_result(r, dir + "/ns.h5");
  const std::string s = describe_result(dir + "/ns.h5");
  CAPTURE(s);
  CHECK(s.find("/snapshots/vorticity") != std::string::npos);
  CHECK(s.find("(5 × 10 × 16)  [1/s]") != std::string::npos);
  CHECK(s.find("/snapshots/t") != std::string::npos);
  CHECK(s.find(fmt::format("history: {} steps", r.viscous->history.size())) != std::string::npos);
  CHECK(s.find("snapshots: 5 stored states") != std::string::npos);
  // The per-state views are summed up in one line, not listed one by one.
  CHECK(s.find("/mesh/snapshots/psi/3") == std::string::npos);
  CHECK(s.find("/mesh/snapshots/") != std::string::npos);
}

TEST_CASE("a steady grid study: its grids and Richardson values in /steady_study, read back", "[io][format][viscous]") {
  const std::string dir = test::temp_dir("ns-study");
  FlowResult r = test::viscous_result_by_hand(0.0, 16, 10, 0);
  SteadyStudy st;
  const std::vector<double> h = {0.08, 0.04, 0.02}, cd = {1.60, 1.53, 1.51}, ld = {2.0, 2.2, 2.25};
  for (size_t k = 0; k < h.size(); ++k) {
    SteadyLevel lv;
    lv.n_theta = 16 << k, lv.n_r = 9 * (1 << k) + 1, lv.h = h[k], lv.C_D = cd[k], lv.C_L = 0.0;
    lv.recirculation = ld[k];
    lv.newton.iterations = 5 - int(k), lv.newton.factorisations = 3 - int(k), lv.newton.wall_seconds = 0.1 * (k + 1);
    lv.newton.residuals = {1.0, 1e-4, 1e-10 / double(k + 1)};
    st.levels.push_back(lv);
  }
  st.C_D = richardson(cd, h), st.recirculation = richardson(ld, h);
  st.converged = true, st.mirror = true, st.message = "3 grids", st.wall_seconds = 0.6;
  r.viscous->steady_study = st;
  write_result(r, dir + "/s.h5");

  const ResultFile f(dir + "/s.h5");
  CHECK(f.dataset("/steady_study/cd") == cd);
  CHECK(f.dataset("/steady_study/n_theta") == std::vector<double>{16, 32, 64});
  CHECK(f.attr_string("/steady_study/seconds", "units") == "s");
  CHECK(f.attr_double("/steady_study", "cd") == st.C_D->value);
  CHECK(f.attr_string("/steady_study", "cd_error_units") == "1");
  // C_L was not extrapolated: listed as undefined, not stored as a number.
  CHECK(f.attr_string("/steady_study", "undefined").find("cl_error") != std::string::npos);

  const FlowResult back = read_result(dir + "/s.h5");
  REQUIRE(back.viscous);
  REQUIRE(back.viscous->steady_study);
  const SteadyStudy& b = *back.viscous->steady_study;
  REQUIRE(b.levels.size() == 3);
  for (size_t k = 0; k < 3; ++k) {
    CHECK(b.levels[k].n_theta == st.levels[k].n_theta);
    CHECK(b.levels[k].n_r == st.levels[k].n_r);
    CHECK(b.levels[k].C_D == cd[k]);
    CHECK(b.levels[k].recirculation == ld[k]);
    CHECK(b.levels[k].newton.factorisations == st.levels[k].newton.factorisations);
    CHECK(b.levels[k].newton.residuals.back() == st.levels[k].newton.residuals.back());
  }
  REQUIRE(b.C_D);
  CHECK(b.C_D->value == st.C_D->value);
  CHECK(b.C_D->error == st.C_D->error);
  CHECK(b.C_D->order == st.C_D->order);
  CHECK(b.C_D->observed == st.C_D->observed);
  CHECK_FALSE(b.C_L);
  CHECK(b.mirror);
  CHECK(b.converged);
  CHECK(b.message == "3 grids");

  const std::string s = describe_result(dir + "/s.h5");
  CAPTURE(s);
  CHECK(s.find("steady grid study") != std::string::npos);
  CHECK(s.find("/steady_study/cd ") != std::string::npos);
  CHECK(s.find(fmt::format("{:.10g}", st.C_D->value)) != std::string::npos);

  // Without a study there is no /steady_study at all.
  r.viscous->steady_study.reset();
  write_result(r, dir + "/u.h5");
  CHECK_FALSE(ResultFile(dir + "/u.h5").has("/steady_study"));
}

TEST_CASE("a partial navier-stokes file says so in inspect and compare", "[io][inspect][compare][viscous]") {
  const std::string dir = test::temp_dir("ns-partial");
  FlowResult r = test::viscous_result_by_hand(1.0, 16, 10, 0);
  write_result(r, dir + "/done.h5");
  r.viscous->partial = true;
  r.viscous->status = "interrupted";
  write_result(r, dir + "/part.h5");
  const std::string s = describe_result(dir + "/part.h5");
  CAPTURE(s);
  CHECK(s.find("\nstatus: interrupted — a PARTIAL result (stopped before its end: /@partial = 1)\n") !=
        std::string::npos);
  const std::string d = describe_result(dir + "/done.h5");
  CHECK(d.find("\nstatus: periodic means converged\n") != std::string::npos);
  CHECK(d.find("PARTIAL") == std::string::npos);

  const Comparison c = compare_results({dir + "/done.h5", dir + "/part.h5"});
  CAPTURE(c.table);
  CHECK(c.table.find("  [2] " + dir + "/part.h5  — NS by hand  (PARTIAL: interrupted)\n") !=
        std::string::npos);
  CHECK(c.table.find("  [1] " + dir + "/done.h5  — NS by hand\n") != std::string::npos);
  // The CSV: a partial column, 0 or 1.
  CHECK(c.csv.rfind("file,title,partial,", 0) == 0);
  CHECK(c.csv.find("\n" + dir + "/done.h5,NS by hand,0,") != std::string::npos);
  CHECK(c.csv.find("\n" + dir + "/part.h5,NS by hand,1,") != std::string::npos);
}

TEST_CASE(
    "/fields/pressure: Bernoulli's for potential flow, the pressure Poisson equation's for navier-stokes",
    "[io][format][viscous]") {
  const std::string dir = test::temp_dir("ns-pressure-description");
  write_result(test::viscous_result_by_hand(1.0, 16, 10, 0), dir + "/ns.h5");
  Case c = test::make_case(1.0, 16);
  c.output.fields.reset();  // every field
  write_result(run_case(c), dir + "/pot.h5");
  const std::string bernoulli = "pressure p = p∞ + ½ρ(U² − |u|²)";
  const std::string poisson =
      "pressure from the pressure Poisson equation ∇²p = 2ρ(∂u_x/∂x ∂u_y/∂y − ∂u_x/∂y ∂u_y/∂x), fixed to p∞ "
      "far upstream";
  CHECK(ResultFile(dir + "/pot.h5").attr_string("/fields/pressure", "description") == bernoulli);
  CHECK(ResultFile(dir + "/ns.h5").attr_string("/fields/pressure", "description") == poisson);
  CHECK(describe_result(dir + "/ns.h5").find("[Pa]  " + poisson + "\n") != std::string::npos);
  CHECK(describe_result(dir + "/ns.h5").find("Bernoulli") == std::string::npos);
  CHECK(describe_result(dir + "/pot.h5").find("[Pa]  " + bernoulli + "\n") != std::string::npos);
}

TEST_CASE("navier-stokes map table: one thread is not called parallel", "[io][sweep]") {
  NsMap m;
  m.base.title = "map";
  m.reynolds = {20.0, 60.0};
  m.alphas = {0.0, 1.0};
  m.n_theta = 48, m.n_r = 40, m.outer_over_a = 20.0;
  m.total_s = 5.27;
  m.threads = 1;
  CHECK(test::line_of(ns_map_table(m), "time") == "time         5.27 s on 1 thread");
  m.threads = 2;
  CHECK(test::line_of(ns_map_table(m), "time") == "time         5.27 s on 2 threads (rows in parallel)");
}
