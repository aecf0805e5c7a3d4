#include "io/inspect.hpp"

#include <fmt/core.h>

#include <cmath>

#include "io/hdf5_io.hpp"
#include "io/report.hpp"
#include "io/inspect.hpp"

namespace magnus {

std::string describe_result(const std::string& path) {
  const ResultFile f(path);
  std::string s;
  s += fmt::format("{}: magnus-flow version {} (written by magnus {})\n", path, f.attr_int("/", "format_version"),
                   f.attr_string("/", "software_version"));
  if (f.has_attr("/", "title")) s += fmt::format("title: {}\n", f.attr_string("/", "title"));
  auto num = [&](const char* obj, const char* name) {
    return f.has_attr(obj, name) ? fmt::format("{:.10g}", f.attr_double(obj, name)) : std::string("undefined");
  };
  s += "\nparameters\n";
  for (const char* k : {"radius", "spin", "spin_ratio", "speed", "density", "pressure_inf", "circulation",
                        "outer_radius"})
    s += fmt::format("  {:<22}{}\n", k, num("/parameters", k));
  for (const char* k : {"far_field", "spacing", "method", "stencil"})
    if (f.has_attr("/parameters", k)) s += fmt::format("  {:<22}{}\n", k, f.attr_string("/parameters", k));
  for (const char* k : {"n_r", "n_theta"})
    if (f.has_attr("/parameters", k)) s += fmt::format("  {:<22}{}\n", k, f.attr_int("/parameters", k));
  s += "\nforces\n";
  for (const char* k : {"lift", "drag", "cl", "cd", "cl_kutta_joukowski", "cl_seed_estimate", "delta_p_top_bottom",
                        "delta_p_seed_estimate", "circulation_measured"})
    s += fmt::format("  {:<22}{}\n", k, num("/forces", k));
  s += "\nerrors\n";
  for (const char* k : {"psi_max_rel", "cp_surface_max_abs", "cl_rel"})
    s += fmt::format("  {:<22}{}\n", k, num("/errors", k));
  s += "\ntiming (s)\n";
  for (const char* k : {"total_s", "assemble_s", "factor_s", "solve_s", "postproc_s"})
    s += fmt::format("  {:<22}{}\n", k, num("/timing", k));
  s += "\ndatasets\n";
  size_t values = 0;
  const auto all = f.datasets();
  for (const auto& [name, shape] : all) {
    std::string dims;
    for (size_t d : shape) dims += (dims.empty() ? "" : " × ") + std::to_string(d);
    const std::string units = f.has_attr(name, "units") ? f.attr_string(name, "units") : "?";
    s += fmt::format("  {:<24}({})  [{}]\n", name, dims, units);
    // Read every value back: HDF5 verifies the checksums (Fletcher-32) on the way, so a damaged file is
    // reported here rather than found later by whoever uses the numbers.
    values += f.dataset(name).size();
  }
  s += fmt::format("\nchecked: {} datasets, {} values read back intact\n", all.size(), values);
  return s;
}

}  // namespace magnus
