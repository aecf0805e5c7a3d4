#include "io/xdmf.hpp"

#include <fmt/core.h>

#include <cmath>

namespace magnus {

namespace {

std::vector<double> closed(const std::vector<double>& f, size_t nr, size_t nt) {
  std::vector<double> out(nr * (nt + 1));
  for (size_t i = 0; i < nr; ++i) {
    std::copy(f.begin() + long(i * nt), f.begin() + long((i + 1) * nt), out.begin() + long(i * (nt + 1)));
    out[i * (nt + 1) + nt] = f[i * nt];
  }
  return out;
}

bool has_velocity(const FlowResult& r) { return !r.fields.u_x.empty() && !r.fields.u_y.empty(); }

}  // namespace

void for_each_xdmf_array(const FlowResult& r, const std::function<void(const XdmfArray&)>& visit) {
  const PolarGrid& g = r.grid;
  const size_t nr = g.n_r, nt = g.n_theta;
  XdmfArray x{"x", {1, nr, nt + 1}, std::vector<double>(nr * (nt + 1)), "m"};
  XdmfArray y{"y", {1, nr, nt + 1}, std::vector<double>(nr * (nt + 1)), "m"};
  for (size_t i = 0; i < nr; ++i)
    for (size_t j = 0; j <= nt; ++j) {
      const double th = j == nt ? 2.0 * M_PI : g.theta[j];
      x.data[i * (nt + 1) + j] = g.r[i] * std::cos(th);
      y.data[i * (nt + 1) + j] = g.r[i] * std::sin(th);
    }
  visit(x);
  visit(y);
  for (const auto& name : field_names()) {
    const auto& f = r.fields.get(name);
    if (!f.empty()) visit({name, {1, nr, nt + 1}, closed(f, nr, nt), field_units(name)});
  }
  if (has_velocity(r)) {
    XdmfArray v{"velocity", {1, nr, nt + 1, 3}, std::vector<double>(nr * (nt + 1) * 3, 0.0), "m/s"};
    for (size_t i = 0; i < nr; ++i)
      for (size_t j = 0; j <= nt; ++j) {
        const size_t src = i * nt + (j % nt), dst = 3 * (i * (nt + 1) + j);
        v.data[dst] = r.fields.u_x[src];
        v.data[dst + 1] = r.fields.u_y[src];
      }
    visit(v);
  }
}

std::string xdmf_text(const FlowResult& r, const std::string& h5_name) {
  const size_t nr = r.grid.n_r, nt1 = r.grid.n_theta + 1;
  auto item = [&](const std::string& name, const std::string& dims) {
    return fmt::format(
        "        <DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
        "{}:/xdmf/{}</DataItem>\n", dims, h5_name, name);
  };
  const std::string d2 = fmt::format("1 {} {}", nr, nt1), d3 = fmt::format("1 {} {} 3", nr, nt1);
  std::string s = "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                  "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  s += fmt::format("    <Grid Name=\"{}\" GridType=\"Uniform\">\n", "magnus");
  s += fmt::format("      <Topology TopologyType=\"3DSMesh\" Dimensions=\"{}\"/>\n", d2);
  s += "      <Geometry GeometryType=\"X_Y\">\n" + item("x", d2) + item("y", d2) + "      </Geometry>\n";
  for (const auto& name : field_names())
    if (!r.fields.get(name).empty())
      s += fmt::format("      <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n", name) +
           item(name, d2) + "      </Attribute>\n";
  if (has_velocity(r))
    s += "      <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n" +
         item("velocity", d3) + "      </Attribute>\n";
  s += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return s;
}

}  // namespace magnus
