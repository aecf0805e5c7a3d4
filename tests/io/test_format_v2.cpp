// Format version 2: one schema table, units on everything, dimension scales, no NaN, the
// XDMF sidecar that validates and closes the ring by connectivity, optional compression, the size figure,
// and readers that still take version 1 files.
#include <fmt/core.h>
#include <hdf5.h>
#include <hdf5_hl.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include "app/compare.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/result_reader.hpp"
#include "io/schema.hpp"
#include "io/xdmf.hpp"
#include "support.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

FlowResult all_fields(double alpha, int n_theta) {
  Case c = test::make_case(alpha, n_theta);
  c.output.fields.reset();
  c.source_text = "title = \"v2\"\n";
  return run_case(c);
}

std::string data_file(const std::string& name) {
  return std::string(MAGNUS_SOURCE_DIR) + "/tests/data/" + name;
}

bool has_command(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()) == 0; }

}  // namespace

TEST_CASE("format 2: the file holds exactly the schema's keys, each numeric attribute with its unit",
          "[io][format]") {
  const std::string dir = test::temp_dir("v2-schema");
  const FlowResult r = all_fields(1.0, 32);
  write_result(r, dir + "/r.h5");
  const ResultFile f(dir + "/r.h5");
  // The schema's fields are the ones a run can write, in the same order.
  std::vector<std::string> names;
  for (const DatasetSpec* d : field_datasets()) names.push_back(d->path.substr(8));
  REQUIRE(names == field_names());
  for (const DatasetSpec* d : field_datasets())
    REQUIRE(applies(d->models, r) == field_of_model(d->path.substr(8), FlowModel::potential));
  for (const char* group : {"/", "/parameters", "/forces", "/errors", "/timing"})
    for (const auto& name : f.attributes(group)) {
      CAPTURE(group, name);
      std::string key = name;
      if (key.size() > 6 && key.compare(key.size() - 6, 6, "_units") == 0) key.resize(key.size() - 6);
      REQUIRE((key == "undefined" || find_attribute(group, key) != nullptr));
    }
  for (const AttrSpec& a : result_attributes()) {
    CAPTURE(a.group, a.name);
    if (!applies(a.models, r)) {  // another model's entry: absent, not listed as undefined
      REQUIRE_FALSE(f.has_attr(a.group, a.name));
      continue;
    }
    if (a.kind == AttrKind::text) {
      REQUIRE(f.attr_is_text(a.group, a.name));
      continue;
    }
    const auto v = a.number(r);
    REQUIRE(f.has_attr(a.group, a.name) == bool(v));
    if (v) REQUIRE(f.attr_string(a.group, units_attribute(a.name)) == a.units);
  }
  REQUIRE(f.attr_string("/errors", "undefined") == "cl_rel_estimated");
  for (const auto& [path, shape] : f.datasets()) {
    CAPTURE(path);
    REQUIRE((find_dataset(path) != nullptr || path.rfind("/mesh/", 0) == 0));
    REQUIRE(f.attr_string(path, "units") == dataset_units(path));
  }
}

TEST_CASE("format 2: r and θ are dimension scales of every field and θ of the surface", "[io][format]") {
  const std::string dir = test::temp_dir("v2-scales");
  const FlowResult r = all_fields(0.5, 16);
  write_result(r, dir + "/r.h5");
  const hid_t file = H5Fopen((dir + "/r.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t rs = H5Dopen2(file, "/grid/r", H5P_DEFAULT), ts = H5Dopen2(file, "/grid/theta", H5P_DEFAULT);
  CHECK(H5DSis_scale(rs) > 0);
  CHECK(H5DSis_scale(ts) > 0);
  std::vector<std::string> gridded = {"/grid/x", "/grid/y"};
  for (const auto& n : field_names())
    if (field_of_model(n, FlowModel::potential)) gridded.push_back("/fields/" + n);
  for (const auto& p : gridded) {
    CAPTURE(p);
    const hid_t d = H5Dopen2(file, p.c_str(), H5P_DEFAULT);
    CHECK(H5DSis_attached(d, rs, 0) > 0);
    CHECK(H5DSis_attached(d, ts, 1) > 0);
    H5Dclose(d);
  }
  for (const char* p :
       {"/surface/u_theta", "/surface/pressure", "/surface/cp", "/surface/cp_exact", "/surface/theta"}) {
    CAPTURE(p);
    const hid_t d = H5Dopen2(file, p, H5P_DEFAULT);
    CHECK(H5DSis_attached(d, ts, 0) > 0);
    H5Dclose(d);
  }
  H5Dclose(rs);
  H5Dclose(ts);
  H5Fclose(file);
}

TEST_CASE("read_result gives back every attribute, field and stagnation point written", "[io][format]") {
  const std::string dir = test::temp_dir("v2-read");
  const FlowResult r = all_fields(1.0, 32);
  write_result(r, dir + "/r.h5");
  const FlowResult b = read_result(dir + "/r.h5");
  for (const AttrSpec& a : result_attributes()) {
    CAPTURE(a.name);
    if (a.kind == AttrKind::text)
      REQUIRE(a.text(b) == a.text(r));
    else
      REQUIRE(a.number(b) == a.number(r));
  }
  for (const DatasetSpec& d : result_datasets()) {
    CAPTURE(d.path);
    REQUIRE(d.values(b) == d.values(r));
  }
  REQUIRE(b.stagnation.size() == r.stagnation.size());
  REQUIRE(b.stagnation_exact.size() == r.stagnation_exact.size());
}

TEST_CASE("the .xmf validates against the XDMF DTD and closes the ring by connectivity",
          "[io][format][xdmf]") {
  const std::string dir = test::temp_dir("v2-xdmf");
  const FlowResult r = all_fields(1.0, 16);
  write_result(r, dir + "/flow.h5");
  const std::string xmf = dir + "/flow.xmf";
  REQUIRE(fs::exists(xmf));
  // The DOCTYPE names Xdmf.dtd beside the file.
  fs::copy_file(data_file("Xdmf.dtd"), dir + "/Xdmf.dtd");
  REQUIRE(has_command("xmllint --version"));  // scripts/setup.sh installs libxml2-utils
  const std::string cmd =
      "xmllint --noout --dtdvalid '" + data_file("Xdmf.dtd") + "' '" + xmf + "' 2>'" + dir + "/lint.txt'";
  CAPTURE(test::slurp(dir + "/lint.txt"));
  REQUIRE(std::system(cmd.c_str()) == 0);
  REQUIRE(test::slurp(dir + "/lint.txt").empty());

  const ResultFile f(dir + "/flow.h5");
  const size_t nr = r.grid.n_r, nt = r.grid.n_theta;
  std::vector<size_t> shape;
  const auto q = f.dataset("/mesh/quads", &shape);
  REQUIRE(shape == std::vector<size_t>{(nr - 1) * nt, 4});
  for (double v : q) REQUIRE((v >= 0 && v < double(nr * nt)));
  // Every cell of the last column joins column n_θ − 1 to column 0: no duplicated seam nodes.
  for (size_t i = 0; i + 1 < nr; ++i) {
    const size_t k = i * nt + nt - 1;
    REQUIRE(q[4 * k] == double(i * nt + nt - 1));
    REQUIRE(q[4 * k + 2] == double((i + 1) * nt));
    REQUIRE(q[4 * k + 3] == double(i * nt));
  }
  // Each node is used by 4 cells inside, 2 on the body and the outer boundary: the ring is closed.
  std::vector<int> uses(nr * nt, 0);
  for (double v : q) ++uses[size_t(v)];
  for (size_t n = 0; n < nr * nt; ++n) REQUIRE(uses[n] == (n < nt || n >= (nr - 1) * nt ? 2 : 4));
  // The views read the stored values: points (x, y, 0), the fields flattened, velocity (u_x, u_y, 0).
  const auto pts = f.dataset("/mesh/points"), gx = f.dataset("/grid/x"), gy = f.dataset("/grid/y");
  for (size_t n = 0; n < nr * nt; ++n) {
    REQUIRE(pts[3 * n] == gx[n]);
    REQUIRE(pts[3 * n + 1] == gy[n]);
    REQUIRE(pts[3 * n + 2] == 0.0);
  }
  REQUIRE(f.dataset("/mesh/psi") == r.fields.psi);
  const auto vel = f.dataset("/mesh/velocity");
  for (size_t n = 0; n < nr * nt; ++n) {
    REQUIRE(vel[3 * n] == r.fields.u_x[n]);
    REQUIRE(vel[3 * n + 1] == r.fields.u_y[n]);
    REQUIRE(vel[3 * n + 2] == 0.0);
  }
  const std::string text = test::slurp(xmf);
  REQUIRE(text.find(fmt::format("NumberOfElements=\"{}\"", (nr - 1) * nt)) != std::string::npos);
}

TEST_CASE("the file is at most 1.15 × the bytes of its fields and grid", "[io][format][size]") {
  const std::string dir = test::temp_dir("v2-size");
  const FlowResult r = all_fields(1.0, 128);
  write_result(r, dir + "/s.h5");
  const ResultFile f(dir + "/s.h5");
  size_t payload = 0;
  for (const auto& [path, shape] : f.datasets()) {
    if (path.rfind("/fields/", 0) != 0 && path.rfind("/grid/", 0) != 0) continue;
    size_t n = 8;
    for (size_t d : shape) n *= d;
    payload += n;
  }
  const double ratio = double(fs::file_size(dir + "/s.h5")) / double(payload);
  CAPTURE(ratio, payload);
  REQUIRE(ratio <= 1.15);
}

TEST_CASE("compression: gzip level 1–9 shrinks the file and keeps every value", "[io][format]") {
  const std::string dir = test::temp_dir("v2-gzip");
  const FlowResult r = all_fields(1.0, 64);
  write_result(r, dir + "/plain.h5");
  write_result(r, dir + "/gzip.h5", 6);
  REQUIRE(fs::file_size(dir + "/gzip.h5") < fs::file_size(dir + "/plain.h5"));
  const FlowResult b = read_result(dir + "/gzip.h5");
  REQUIRE(b.fields.psi == r.fields.psi);
  REQUIRE(b.fields.cp == r.fields.cp);
  REQUIRE(describe_result(dir + "/gzip.h5").find("values read back intact") != std::string::npos);
  REQUIRE_THROWS_WITH(write_result(r, dir + "/bad.h5", 10), Catch::Contains("0–9"));
  REQUIRE_FALSE(fs::exists(dir + "/bad.h5"));
}

TEST_CASE("inspect lists every attribute with its unit, and the stagnation coordinates", "[io][format]") {
  const std::string dir = test::temp_dir("v2-inspect");
  write_result(all_fields(1.0, 32), dir + "/r.h5");
  const std::string s = describe_result(dir + "/r.h5");
  for (const char* k : {"magnus_S ", "magnus_S_exact", "lift_kutta_joukowski", "delta_p_top_bottom_exact",
                        "circulation_rel", "circulation_model", "outer_radius_requested", "model: potential"})
    CHECK(s.find(k) != std::string::npos);
  CHECK(s.find("[kg/m]") != std::string::npos);
  CHECK(s.find("[N/m]") != std::string::npos);
  CHECK(s.find("cl_rel_estimated") != std::string::npos);  // undefined, listed as such
  CHECK(s.find("stagnation points") != std::string::npos);
  CHECK(s.find("rad (") != std::string::npos);
  CHECK(s.find("/mesh/quads") != std::string::npos);
}

TEST_CASE("version 1 files are still read: read_result, inspect, compare", "[io][format]") {
  const std::string v1 = data_file("v1_result.h5");
  REQUIRE(fs::exists(v1));
  const FlowResult r = read_result(v1);
  REQUIRE(r.grid.n_theta == 16);
  REQUIRE(r.forces.cl);
  REQUIRE_FALSE(r.fields.psi.empty());
  REQUIRE(r.stagnation.size() == 2);
  const std::string s = describe_result(v1);
  CHECK(s.find("magnus-flow version 1") != std::string::npos);
  CHECK(s.find("[kg/m]") != std::string::npos);
  const Comparison c = compare_results({v1, v1});
  CHECK(c.csv.find(fmt::format("{:.17g}", *r.forces.cl)) != std::string::npos);
  CHECK(describe_result(data_file("v1_sweep.h5")).find("magnus-sweep version 1") != std::string::npos);
}
