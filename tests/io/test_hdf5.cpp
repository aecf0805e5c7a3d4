#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/report.hpp"
#include "io/schema.hpp"
#include "support.hpp"

using namespace magnus;

namespace {

void require_equal(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t k = 0; k < a.size(); ++k) REQUIRE(a[k] == b[k]);
}

}  // namespace

TEST_CASE("HDF5 round trip: every dataset and attribute of format 2, with units, as computed",
          "[postproc][hdf5]") {
  const std::string dir = test::temp_dir("hdf5");
  Case c = test::make_case(1.0, 32);
  c.output.fields.reset();  // all fields
  c.source_text = "title = \"round trip\"\n";
  const FlowResult r = run_case(c);
  const std::string path = dir + "/r.h5";
  write_result(r, path);
  REQUIRE(std::filesystem::exists(dir + "/r.xmf"));
  const ResultFile f(path);
  REQUIRE(f.attr_string("/", "format") == "magnus-flow");
  REQUIRE(f.attr_int("/", "format_version") == 2);
  REQUIRE(f.attr_string("/", "model") == "potential");
  REQUIRE(f.attr_string("/", "case") == c.source_text);
  REQUIRE_FALSE(f.attr_string("/", "software_version").empty());
  const size_t nr = r.grid.n_r, nt = r.grid.n_theta;
  std::vector<size_t> shape;
  for (const auto& name : field_names()) {
    if (!field_of_model(name, FlowModel::potential)) continue;
    const std::string ds = "/fields/" + name;
    const auto v = f.dataset(ds, &shape);
    REQUIRE(shape == std::vector<size_t>{nr, nt});
    require_equal(v, r.fields.get(name));
    REQUIRE(f.attr_string(ds, "units") == field_units(name));
  }
  require_equal(f.dataset("/grid/r", &shape), r.grid.r);
  REQUIRE(shape == std::vector<size_t>{nr});
  require_equal(f.dataset("/grid/theta"), r.grid.theta);
  for (const char* ds : {"/grid/x", "/grid/y"}) {
    f.dataset(ds, &shape);
    REQUIRE(shape == std::vector<size_t>{nr, nt});
  }
  const auto gx = f.dataset("/grid/x"), gy = f.dataset("/grid/y");
  for (size_t i = 0; i < nr; ++i)
    for (size_t j = 0; j < nt; ++j) {
      REQUIRE(gx[i * nt + j] == Approx(r.grid.r[i] * std::cos(r.grid.theta[j])).margin(1e-15 * r.grid.r[i]));
      REQUIRE(gy[i * nt + j] == Approx(r.grid.r[i] * std::sin(r.grid.theta[j])).margin(1e-15 * r.grid.r[i]));
    }
  require_equal(f.dataset("/surface/theta"), r.surface.theta);
  require_equal(f.dataset("/surface/u_theta"), r.surface.u_theta);
  require_equal(f.dataset("/surface/pressure"), r.surface.pressure);
  require_equal(f.dataset("/surface/cp"), r.surface.cp);
  require_equal(f.dataset("/surface/cp_exact"), r.surface.cp_exact);
  for (const auto& [name, dims] : f.datasets()) {
    CAPTURE(name);
    REQUIRE(f.has_attr(name, "units"));
  }
  const std::pair<const char*, double> params[] = {{"radius", c.scene.radius},
                                                   {"spin", c.scene.spin},
                                                   {"spin_ratio", c.scene.spin_ratio()},
                                                   {"speed", c.scene.speed},
                                                   {"density", c.scene.density},
                                                   {"pressure_inf", c.scene.pressure_inf},
                                                   {"outer_radius", r.grid.outer_radius() / r.grid.a},
                                                   {"outer_radius_requested", c.grid.outer_radius}};
  for (const auto& [name, value] : params) {
    CAPTURE(name);
    REQUIRE(f.attr_double("/parameters", name) == value);
  }
  REQUIRE(f.attr_double("/parameters", "circulation") == c.scene.Gamma());
  REQUIRE(f.attr_int("/parameters", "n_r") == long(nr));
  REQUIRE(f.attr_int("/parameters", "n_theta") == long(nt));
  REQUIRE(f.attr_string("/parameters", "far_field") == "exact");
  REQUIRE(f.attr_string("/parameters", "spacing") == "geometric");
  REQUIRE(f.attr_string("/parameters", "method") == "fft");
  REQUIRE(f.attr_string("/parameters", "stencil") == "5-point");
  REQUIRE(f.attr_double("/forces", "lift") == r.forces.lift);
  REQUIRE(f.attr_double("/forces", "drag") == r.forces.drag);
  REQUIRE(f.attr_double("/forces", "cl") == *r.forces.cl);
  REQUIRE(f.attr_double("/forces", "cd") == *r.forces.cd);
  REQUIRE(f.attr_double("/forces", "cl_kutta_joukowski") == *r.forces.cl_kutta_joukowski);
  REQUIRE(f.attr_double("/forces", "cl_seed_estimate") == *r.forces.cl_seed_estimate);
  REQUIRE(f.attr_double("/forces", "delta_p_top_bottom") == r.forces.delta_p_top_bottom);
  REQUIRE(f.attr_double("/forces", "delta_p_seed_estimate") == r.forces.delta_p_seed_estimate);
  REQUIRE(f.attr_double("/forces", "circulation_measured") == r.forces.circulation_measured);
  REQUIRE(f.attr_double("/errors", "psi_max_rel") == r.errors.psi_max_rel);
  REQUIRE(f.attr_double("/errors", "cp_surface_max_abs") == *r.errors.cp_surface_max_abs);
  REQUIRE(f.attr_double("/errors", "cl_rel") == r.errors.cl_rel);
  for (const char* a : {"total_s", "assemble_s", "factor_s", "solve_s", "postproc_s"})
    REQUIRE(f.attr_double("/timing", a) >= 0.0);
  // Format 2: every numeric group attribute has its unit beside it, from the schema table.
  for (const AttrSpec& a : result_attributes()) {
    CAPTURE(a.group, a.name);
    if (a.kind == AttrKind::text || !f.has_attr(a.group, a.name)) continue;
    REQUIRE(f.attr_string(a.group, units_attribute(a.name)) == a.units);
  }
  REQUIRE(f.attr_string("/forces", "magnus_S_units") == "kg/m");
  REQUIRE(f.attr_double("/forces", "magnus_S_exact") == r.forces.magnus_S_exact);
  // Each field stored once: no seam-closed copies.
  REQUIRE_FALSE(f.has("/xdmf"));
  REQUIRE(f.attr_string("/stagnation/theta", "units") == "rad");
}

TEST_CASE("only the fields asked for are written, U = 0 marks Cp undefined", "[postproc][hdf5]") {
  const std::string dir = test::temp_dir("hdf5-sel");
  Case c = test::make_case(0.0, 16);
  c.scene.speed = 0.0;
  c.scene.spin = 10.0;
  c.output.fields = {"psi", "u_theta"};
  const FlowResult r = run_case(c);
  REQUIRE(r.fields.cp.empty());
  REQUIRE(r.fields.pressure.empty());
  write_result(r, dir + "/sel.h5");
  const ResultFile f(dir + "/sel.h5");
  REQUIRE(f.has("/fields/psi"));
  REQUIRE(f.has("/fields/u_theta"));
  REQUIRE_FALSE(f.has("/fields/cp"));
  REQUIRE_FALSE(f.has("/fields/u_x"));
  REQUIRE_FALSE(f.has_attr("/forces", "cl"));
  REQUIRE(f.attr_string("/forces", "undefined").find("cl") != std::string::npos);
  REQUIRE(f.has_attr("/forces", "lift"));
  std::ifstream xmf(dir + "/sel.xmf");
  const std::string text((std::istreambuf_iterator<char>(xmf)), std::istreambuf_iterator<char>());
  REQUIRE(text.find("TopologyType=\"Quadrilateral\"") != std::string::npos);
  REQUIRE(text.find("GeometryType=\"XYZ\"") != std::string::npos);
  REQUIRE(text.find("sel.h5:/mesh/psi") != std::string::npos);
  REQUIRE(text.find("/mesh/cp") == std::string::npos);
  REQUIRE(text.find("/mesh/velocity") == std::string::npos);
}

TEST_CASE("reading a foreign, truncated or missing file gives one clear error", "[postproc][hdf5]") {
  const std::string dir = test::temp_dir("hdf5-bad");
  { std::ofstream(dir + "/text.h5") << "not hdf5 at all\n"; }
  REQUIRE_THROWS_WITH(ResultFile(dir + "/text.h5"), Catch::Contains("not an HDF5 file"));
  REQUIRE_THROWS_WITH(ResultFile(dir + "/missing.h5"), Catch::Contains("cannot read"));
  // A complete result, cut in half.
  write_result(run_case(test::make_case(1.0, 16)), dir + "/full.h5");
  const auto size = std::filesystem::file_size(dir + "/full.h5");
  std::filesystem::copy_file(dir + "/full.h5", dir + "/cut.h5");
  std::filesystem::resize_file(dir + "/cut.h5", size / 2);
  REQUIRE_THROWS_AS(describe_result(dir + "/cut.h5"), std::runtime_error);
}
