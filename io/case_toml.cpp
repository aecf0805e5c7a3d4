// The resolved case as TOML (io/case_file.hpp's to_toml): what a result stores as its case.
#include <fmt/core.h>

#include "io/case_file.hpp"

namespace magnus {

namespace {

/// A TOML float: the shortest text that reads back exactly, with ".0" when it would read as an integer.
std::string num(double v) {
  std::string s = fmt::format("{}", v);
  return s.find_first_of(".eE") == std::string::npos ? s + ".0" : s;
}

/// A TOML basic string: quotes, backslashes and control characters escaped.
std::string str(const std::string& v) {
  std::string q = "\"";
  for (char ch : v) {
    if (ch == '"' || ch == '\\') q += '\\';
    if (ch == '\n') {
      q += "\\n";
      continue;
    }
    // TOML basic strings may not hold control characters other than tab: escape them all.
    if ((unsigned char)ch < 0x20 || ch == 0x7F) {
      q += fmt::format("\\u{:04X}", (unsigned char)ch);
      continue;
    }
    q += ch;
  }
  return q + "\"";
}

/// The [grid] section. With a tolerance the grid and stencil are chosen at run time (and stored in
/// /parameters); with a tolerance and no stated spacing the search chooses it too: the text leaves it out.
/// navier-stokes without a stated grid: grid.refine (the scene's rule chooses the grid again from the same
/// keys); the rings' clustering only as stated.
std::string grid_toml(const Case& c, bool ns) {
  std::string t = "\n[grid]\n";
  if (c.grid.tolerance == 0.0 || c.grid.spacing_given)
    t += fmt::format("spacing = {}\n", str(to_string(c.grid.spacing)));
  const bool ns_rule = ns && !c.grid.n_theta_given && c.grid.n_r == 0;
  if (c.grid.tolerance > 0.0)
    t += fmt::format("tolerance = {}\n", num(c.grid.tolerance));
  else if (ns_rule)
    t += fmt::format("refine = {}\n", num(c.grid.refine));
  else
    t += fmt::format("n_theta = {}\nn_r = {}\n", c.grid.n_theta, c.grid.n_r);
  if (ns && c.grid.wall_refinement_given)
    t += fmt::format("wall_refinement = {}\n", num(c.grid.wall_refinement));
  if (ns && c.grid.wall_layer_given) t += fmt::format("wall_layer = {}\n", num(c.grid.wall_layer));
  return t;
}

/// solver.wall_closure's line ("thom" or "jensen": nothing to escape), none for Thom's, the default (left
/// out as in texts before the key).
std::string wall_closure_line(const Case& c) {
  return c.solver.wall_closure == "thom" ? "" : fmt::format("wall_closure = \"{}\"\n", c.solver.wall_closure);
}

/// solver.implicit_rotation's line: none for true, the default (left out as in texts before the key).
std::string implicit_rotation_line(const Case& c) {
  return c.solver.implicit_rotation ? "" : "implicit_rotation = false\n";
}

}  // namespace

std::string to_toml(const Case& c) {
  // A navier-stokes case leaves out the keys of potential flow's circulation, far field and solver (they
  // would be errors), and adds its model, [time] and snapshots; a potential case writes none of these.
  const bool ns = c.model == FlowModel::navier_stokes;
  std::string t = fmt::format("title = {}\n", str(c.title));
  if (ns) t += fmt::format("\n[model]\nflow = {}\n", str(to_string(c.model)));
  // The spin as given when in rev/min (ω follows from it exactly as on reading), else ω.
  t += fmt::format("\n[cylinder]\nradius = {}\n", num(c.scene.radius));
  t += c.scene.rpm_given ? fmt::format("rpm = {}\n", num(*c.scene.rpm_given))
                         : fmt::format("spin = {}\n", num(c.scene.spin));
  if (c.scene.span > 0.0) t += fmt::format("span = {}\n", num(c.scene.span));
  // The world keys only when given (the default direction 0 leaves the text of a plain case as it was).
  t += fmt::format("\n[flow]\nspeed = {}\n", num(c.scene.speed));
  if (c.scene.direction_deg != 0.0) t += fmt::format("direction = {}\n", num(c.scene.direction_deg));
  if (c.scene.course_deg) t += fmt::format("course = {}\n", num(*c.scene.course_deg));
  t += fmt::format("density = {}\npressure = {}\n", num(c.scene.density), num(c.scene.pressure_inf));
  // The viscosity as given: a given Re stays the input (ν follows U and a), not the ν derived from it.
  if (c.scene.reynolds_given)
    t += fmt::format("reynolds = {}\n", num(c.scene.reynolds_value));
  else if (c.scene.viscosity > 0.0)
    t += fmt::format("viscosity = {}\n", num(c.scene.viscosity));
  if (!ns) {
    t += fmt::format("\n[circulation]\nmodel = {}\n", str(c.scene.circulation_given ? "given" : "spin"));
    if (c.scene.circulation_given) t += fmt::format("value = {}\n", num(c.scene.circulation_value));
  }
  t += fmt::format("\n[domain]\nouter_radius = {}\n", num(c.grid.outer_radius));
  if (!ns) t += fmt::format("far_field = {}\n", str(to_string(c.grid.far_field)));
  if (ns)  // as resolved: the scene's rule chose the layer unless the case gave it
    t += fmt::format("absorbing_layer = {}\nabsorbing_strength = {}\n", num(c.grid.absorbing_layer),
                     num(c.grid.absorbing_strength));
  t += grid_toml(c, ns);
  if (!ns) {
    t += fmt::format("\n[solver]\nmethod = {}\n", str(to_string(c.solver.method)));
    if (c.grid.tolerance == 0.0) t += fmt::format("stencil = {}\n", str(to_string(c.solver.stencil)));
  } else {
    t += fmt::format("\n[solver]\nadvection_order = {}\nadvection_order_xi = {}\n{}{}", c.solver.advection_order,
                     c.solver.advection_order_xi, wall_closure_line(c), implicit_rotation_line(c));
    t += fmt::format(
        "\n[time]\nmode = {}\nend = {}\ndt = {}\ncfl = {}\nmean_tolerance = {}\n{}checkpoint_interval = {}\n",
        str(to_string(c.time.mode)), num(c.time.end), num(c.time.dt), num(c.time.cfl),
        num(c.time.mean_tolerance), c.time.stop_on_drift ? "" : "stop_on_drift = false\n",
        num(c.time.checkpoint_interval));
  }
  t += fmt::format("\n[output]\nfile = {}\n", str(c.output.file));
  if (c.output.fields) {
    std::string list;
    for (const auto& f : *c.output.fields) list += (list.empty() ? "" : ", ") + str(f);
    t += fmt::format("fields = [{}]\n", list);
  }
  if (c.output.compression > 0) t += fmt::format("compression = {}\n", c.output.compression);
  if (ns)
    t += fmt::format("snapshots = {}\nsnapshot_interval = {}\n", c.output.snapshots,
                     num(c.output.snapshot_interval));
  return t;
}

}  // namespace magnus
