#include "io/xdmf.hpp"

#include <fmt/core.h>

#include "io/schema.hpp"

namespace magnus {

namespace {

bool has_velocity(const FlowResult& r) { return !r.fields.u_x.empty() && !r.fields.u_y.empty(); }

/// The stored states of a navier-stokes result (0 for any other).
size_t snapshot_count(const FlowResult& r) { return r.viscous ? r.viscous->snapshots.size() : 0; }

/// The fields of each stored state, in the order of the time series' attributes.
const char* const kSnapshotFields[] = {"vorticity", "psi"};

/// Name of a stored field (path /fields/NAME).
std::string field_name(const DatasetSpec& d) { return d.path.substr(d.path.rfind('/') + 1); }

/// Characters XML does not allow bare in an attribute value or text.
std::string xml_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

}  // namespace

std::vector<int> quad_connectivity(size_t n_r, size_t n_theta) {
  std::vector<int> q;
  if (n_r < 2 || n_theta < 2) return q;
  q.reserve(4 * (n_r - 1) * n_theta);
  for (size_t i = 0; i + 1 < n_r; ++i)
    for (size_t j = 0; j < n_theta; ++j) {
      const size_t jn = (j + 1) % n_theta;
      for (size_t node : {i * n_theta + j, (i + 1) * n_theta + j, (i + 1) * n_theta + jn, i * n_theta + jn})
        q.push_back(int(node));
    }
  return q;
}

void write_mesh(const FlowResult& r, H5Writer& w) {
  const size_t nr = r.grid.n_r, nt = r.grid.n_theta, n = nr * nt;
  const H5Writer::id m = w.group("/mesh");
  w.attr(m, "note",
         "for the .xmf sidecar: virtual datasets (views, no storage) of /grid and /fields flattened "
         "to n_r·n_theta nodes, and the quadrilateral connectivity (periodic in theta)");
  w.view(m, "points", {n, 3}, {{"/grid/x", 0}, {"/grid/y", 1}}, "m",
         "node coordinates (x, y, 0), node i·n_theta + j");
  const std::vector<int> q = quad_connectivity(nr, nt);
  w.int_dataset(
      m, "quads", {q.size() / 4, 4}, q.data(), "1",
      "node indices of each quadrilateral, counter-clockwise; column n_theta − 1 wraps to column 0");
  for (const DatasetSpec* d : field_datasets())
    if (!d->values(r).empty()) w.view(m, field_name(*d), {n}, {{d->path, 0}}, d->units, "view of " + d->path);
  if (has_velocity(r))
    w.view(m, "velocity", {n, 3}, {{"/fields/u_x", 0}, {"/fields/u_y", 1}}, "m/s",
           "(u_x, u_y, 0): view of /fields");
  // State k of each stored field: /mesh/snapshots/FIELD/k, a view of /snapshots/FIELD[k] (n_r·n_θ).
  const size_t states = snapshot_count(r);
  if (states == 0) return;
  const H5Writer::id sg = w.group("/mesh/snapshots");
  w.attr(sg, "note", "views of /snapshots: FIELD/k is state k of /snapshots/FIELD, flattened to n_r·n_theta");
  for (const char* field : kSnapshotFields) {
    const std::string source = std::string("/snapshots/") + field;
    const H5Writer::id fg = w.group(std::string("/mesh/snapshots/") + field);
    for (size_t k = 0; k < states; ++k)
      w.view(fg, std::to_string(k), {n}, {{source, 0, long(k)}}, dataset_units(source),
             fmt::format("view of state {} of {}", k, source));
  }
}

std::string xdmf_text(const FlowResult& r, const std::string& h5_name) {
  const size_t nr = r.grid.n_r, nt = r.grid.n_theta, n = nr * nt, cells = (nr - 1) * nt;
  const std::string file = xml_escape(h5_name);
  std::string indent = "        ";
  auto item = [&](const std::string& name, const std::string& dims, const char* type = "Float",
                  int prec = 8) {
    return fmt::format(
        "{}<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"HDF\">"
        "{}:/mesh/{}</DataItem>\n",
        indent, dims, type, prec, file, name);
  };
  std::string s =
      "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  s += fmt::format("    <Grid Name=\"{}\" GridType=\"Uniform\">\n",
                   xml_escape(r.c.title.empty() ? "magnus" : r.c.title));
  s += fmt::format(
           "      <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"{}\" NodesPerElement=\"4\">\n",
           cells) +
       item("quads", fmt::format("{} 4", cells), "Int", 4) + "      </Topology>\n";
  s += "      <Geometry GeometryType=\"XYZ\">\n" + item("points", fmt::format("{} 3", n)) +
       "      </Geometry>\n";
  for (const DatasetSpec* d : field_datasets())
    if (!d->values(r).empty())
      s += fmt::format("      <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n",
                       field_name(*d)) +
           item(field_name(*d), std::to_string(n)) + "      </Attribute>\n";
  if (has_velocity(r))
    s += "      <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n" +
         item("velocity", fmt::format("{} 3", n)) + "      </Attribute>\n";
  s += "    </Grid>\n";
  // The stored states as a time series: one grid per state on the same nodes and quadrilaterals (the same
  // /mesh datasets as the grid above: stored once; an XPath Reference would save nothing on disk and the
  // Xdmf3 readers abort on it), with its time in s.
  if (const size_t states = snapshot_count(r); states > 0) {
    indent = std::string(10, ' ');
    s += "    <Grid Name=\"snapshots\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (size_t k = 0; k < states; ++k) {
      s += fmt::format("      <Grid Name=\"state {}\" GridType=\"Uniform\">\n", k);
      s += fmt::format("        <Time Value=\"{:.17g}\" />\n", r.viscous->snapshots[k].t);
      s += fmt::format(
               "        <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"{}\" "
               "NodesPerElement=\"4\">\n",
               cells) +
           item("quads", fmt::format("{} 4", cells), "Int", 4) + "        </Topology>\n";
      s += "        <Geometry GeometryType=\"XYZ\">\n" + item("points", fmt::format("{} 3", n)) +
           "        </Geometry>\n";
      for (const char* field : kSnapshotFields)
        s +=
            fmt::format("        <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n", field) +
            item(fmt::format("snapshots/{}/{}", field, k), std::to_string(n)) + "        </Attribute>\n";
      s += "      </Grid>\n";
    }
    s += "    </Grid>\n";
  }
  s += "  </Domain>\n</Xdmf>\n";
  return s;
}

}  // namespace magnus
