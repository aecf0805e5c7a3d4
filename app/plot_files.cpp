#include "app/plot_files.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "io/case_keys.hpp"
#include "io/hdf5_io.hpp"
#include "io/inspect.hpp"
#include "io/ns_sweep_file.hpp"
#include "io/reference_file.hpp"
#include "io/result_reader.hpp"
#include "io/stability_file.hpp"
#include "io/rotor_data.hpp"
#include "plot/ns_map_plot.hpp"

namespace magnus {

PlotSize parse_plot_size(const std::string& text) {
  const auto x = text.find_first_of("xX");
  auto part = [&](const std::string& s) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) return -1;
    return std::atoi(s.c_str());
  };
  const int w = x == std::string::npos ? -1 : part(text.substr(0, x));
  const int h = x == std::string::npos ? -1 : part(text.substr(x + 1));
  if (w < 0 || h < 0)
    throw std::invalid_argument(
        fmt::format("--size '{}': expected WIDTHxHEIGHT in pixels, e.g. 900x700", cut_input(text)));
  if (w < 16 || h < 16 || w > 16384 || h > 16384)
    throw std::invalid_argument(fmt::format("--size '{}': each side must be 16 to 16384 pixels", text));
  return {w, h};
}

LiftSweep read_lift_sweep(const std::string& path) {
  const ResultFile f(path, {"magnus-sweep"});
  LiftSweep s;
  s.by_circulation = f.has_attr("/", "variable") && f.attr_string("/", "variable") == "circulation";
  const std::string xcol = s.by_circulation ? "/sweep/circulation" : "/sweep/alpha";
  s.x = f.dataset(xcol);
  s.cl = f.dataset("/sweep/cl");
  if (s.x.size() != s.cl.size())
    throw std::runtime_error(fmt::format("'{}': /sweep columns differ in length", path));
  auto param = [&](const char* name, double dflt) {
    return f.has_attr("/parameters", name) ? f.attr_double("/parameters", name) : dflt;
  };
  s.base.radius = param("radius", 0.0);
  s.base.speed = param("speed", 0.0);
  if (!(s.base.radius > 0.0) || !(s.base.speed > 0.0))
    throw std::runtime_error(fmt::format("'{}': /parameters radius and speed must be positive", path));
  s.base.spin = param("spin", 0.0);
  s.base.viscosity = param("viscosity", 0.0);  // older files: no Re, every overlay drawn
  s.base.circulation_given = s.by_circulation;
  s.title = f.has_attr("/", "title") ? f.attr_string("/", "title") : std::string();
  s.n_theta = int(param("n_theta", 0.0));
  s.n_r = int(param("n_r", 0.0));
  return s;
}

namespace {

std::string stem_of(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string output_base(const std::string& path, const std::string& dir_in) {
  namespace fs = std::filesystem;
  std::string dir = dir_in;
  if (dir.empty()) {
    dir = fs::path(path).parent_path().string();
    if (dir.empty()) dir = ".";
  } else {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
      if (fs::exists(dir, ec)) throw std::runtime_error(fmt::format("-o '{}': not a directory", dir));
      fs::create_directories(dir, ec);
      if (ec)
        throw std::runtime_error(fmt::format("-o '{}': cannot create the directory: {}", dir, ec.message()));
    }
  }
  return (fs::path(dir) / stem_of(path)).string();
}

/// The lift sweep of a sweep file, with the viscous reference and rotor data (spin sweeps): <base>_cl.png.
void plot_lift_sweep_file(const std::string& path, const std::string& dir, PlotSize size, PlotOutcome& out) {
  const LiftSweep s = read_lift_sweep(path);
  std::optional<ViscousReference> ref;
  if (!s.by_circulation) try {
      ref = load_viscous_reference(viscous_reference_path());
    } catch (const std::exception& e) {
      out.skipped.push_back(std::string("viscous reference data not shown: ") + e.what());
    }
  const RotorData* rotor = s.by_circulation ? nullptr : shipped_rotor_data();
  if (!s.by_circulation && !rotor) out.skipped.push_back("rotor data not shown: " + rotor_data_error());
  const CurveFigure f = lift_figure(s, ref ? &*ref : nullptr, rotor);
  const std::string png = output_base(path, dir) + "_cl.png";
  plot_curves(f.page, f.lines, f.points, png, size);
  out.written.push_back(png);
}

/// One picture of a result: drawn to base + suffix when `have`, else `skipped` noted.
template <class Draw>
void picture(PlotOutcome& out, bool have, const std::string& skipped, const std::string& png, Draw draw) {
  if (!have) {
    out.skipped.push_back(skipped);
    return;
  }
  draw(png);
  out.written.push_back(png);
}

void plot_curve_figure(const CurveFigure& f, const std::string& png, PlotSize size) {
  plot_curves(f.page, f.lines, f.points, png, size);
}

/// A navier-stokes result's vorticity, forces against time and wall shear stress.
void plot_viscous_pictures(const FlowResult& r, const std::string& path, const std::string& base,
                           PlotSize size, const std::optional<PlotWindow>& window, PlotOutcome& out) {
  picture(out, !r.fields.vorticity.empty(),
          fmt::format("vorticity skipped: '{}' has no /fields/vorticity (see output.fields)", path),
          base + "_vorticity.png",
          [&](const std::string& png) { plot_contour_field(vorticity_picture(r, window), png, size); });
  picture(out, !r.viscous->history.empty(),
          fmt::format("forces against time skipped: '{}' has no /history", path), base + "_forces.png",
          [&](const std::string& png) { plot_curve_figure(force_history_figure(r), png, size); });
  picture(out, !r.surface.shear_stress.empty(),
          fmt::format("wall shear stress skipped: '{}' has no /surface/shear_stress", path),
          base + "_shear.png",
          [&](const std::string& png) { plot_curve_figure(shear_stress_figure(r), png, size); });
}

/// The pictures of a result file: those its data allow, the others noted in out.skipped.
void plot_result_pictures(const std::string& path, const std::string& dir, PlotSize size,
                          const std::optional<PlotWindow>& window, PlotOutcome& out) {
  const FlowResult r = read_result(path);
  window_for(r, window);  // a window off the grid is refused before any directory or file is made
  const std::string base = output_base(path, dir);
  const double U = r.c.scene.speed;
  picture(out, !r.fields.psi.empty(),
          fmt::format("streamlines skipped: '{}' has no /fields/psi (see output.fields)", path),
          base + "_streamlines.png",
          [&](const std::string& png) { plot_streamlines(streamline_picture(r, window), png, size); });
  picture(out, !r.fields.cp.empty(),
          U > 0.0 ? fmt::format("Cp field skipped: '{}' has no /fields/cp (see output.fields)", path)
                  : std::string("Cp field skipped: Cp is undefined when U = 0"),
          base + "_cp.png",
          [&](const std::string& png) { plot_contour_field(cp_picture(r, window), png, size); });
  picture(out, !r.surface.cp.empty() && U > 0.0,
          U > 0.0 ? fmt::format("surface Cp skipped: '{}' has no /surface/cp", path)
                  : std::string("surface Cp skipped: Cp is undefined when U = 0"),
          base + "_surface_cp.png",
          [&](const std::string& png) { plot_curve_figure(surface_cp_figure(r), png, size); });
  if (r.viscous) plot_viscous_pictures(r, path, base, size, window, out);
  if (out.written.empty()) {
    std::string why;
    for (const auto& s : out.skipped) why += (why.empty() ? "" : "; ") + s;
    throw std::runtime_error(fmt::format("nothing to plot in '{}': {}", path, why));
  }
}

}  // namespace

PlotOutcome plot_result_file(const std::string& path, const std::string& dir, PlotSize size,
                             const std::optional<PlotWindow>& window, const std::vector<std::string>& onset_files) {
  PlotOutcome out;
  // A sweep file draws C_L(α) (or C_L(Γ)); anything else goes to the result reader and its messages.
  bool sweep = false, ns_map = false;
  try {
    const ResultFile f(path, {"magnus-sweep"});
    sweep = f.format() == "magnus-sweep";
    ns_map = f.has_attr("/", "model") && f.attr_string("/", "model") == "navier-stokes";
  } catch (const std::exception&) {
    sweep = false;  // not a sweep: the result reader below says what it is
  }
  if (sweep) check_result(path);  // what inspect refuses is refused here too (results: in read_result)
  if (!onset_files.empty() && !ns_map)
    throw std::runtime_error("--onset3d: only for the S(Re, α) map of a navier-stokes sweep, not '" + path + "'");
  std::vector<Onset3d> onset;
  for (const std::string& f : onset_files) onset.push_back(read_onset3d(f));
  if (ns_map) {  // the viscous S(Re, α) map: S/(2πρa²) against α per Re
    const std::string png = output_base(path, dir) + "_s_map.png";
    plot_ns_map(read_ns_map_hdf5(path), png, size, onset);
    out.written.push_back(png);
  } else if (sweep) {
    plot_lift_sweep_file(path, dir, size, out);
  } else {
    plot_result_pictures(path, dir, size, window, out);
  }
  return out;
}

void command_plot(const std::string& path, const std::string& dir, const std::string& size,
                  const std::string& window, bool quiet, const std::vector<std::string>& onset_files) {
  const PlotSize sz = size.empty() ? PlotSize{} : parse_plot_size(size);
  std::optional<PlotWindow> win;
  if (!window.empty()) win = parse_plot_window(window);
  const PlotOutcome o = plot_result_file(path, dir, sz, win, onset_files);
  for (const auto& s : o.skipped) std::fprintf(stderr, "magnus: note: %s\n", s.c_str());
  if (!quiet)
    for (const auto& w : o.written) std::printf("%s\n", w.c_str());
}

}  // namespace magnus
