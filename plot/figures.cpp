#include "plot/figures.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "io/result_reader.hpp"

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
    throw std::invalid_argument(fmt::format("--size '{}': expected WIDTHxHEIGHT in pixels, e.g. 900x700", text));
  if (w < 16 || h < 16 || w > 16384 || h > 16384)
    throw std::invalid_argument(fmt::format("--size '{}': each side must be 16 to 16384 pixels", text));
  return {w, h};
}

namespace {

std::string stem_of(const std::string& path) {
  const std::filesystem::path p(path);
  return p.stem().string();
}

}  // namespace

PlotOutcome plot_result_file(const std::string& path, const std::string& dir_in, PlotSize size) {
  const FlowResult r = read_result(path);
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
      if (ec) throw std::runtime_error(fmt::format("-o '{}': cannot create the directory: {}", dir, ec.message()));
    }
  }
  const std::string base = (fs::path(dir) / stem_of(path)).string();
  PlotOutcome out;
  const double U = r.c.scene.speed;
  if (r.fields.psi.empty()) {
    out.skipped.push_back(fmt::format("streamlines skipped: '{}' has no /fields/psi (see output.fields)", path));
  } else {
    plot_streamlines(r, base + "_streamlines.png", size);
    out.written.push_back(base + "_streamlines.png");
  }
  if (r.fields.cp.empty()) {
    out.skipped.push_back(U > 0.0 ? fmt::format("Cp field skipped: '{}' has no /fields/cp (see output.fields)", path)
                                  : std::string("Cp field skipped: Cp is undefined when U = 0"));
  } else {
    plot_cp_field(r, base + "_cp.png", size);
    out.written.push_back(base + "_cp.png");
  }
  if (r.surface.cp.empty() || !(U > 0.0)) {
    out.skipped.push_back(U > 0.0 ? fmt::format("surface Cp skipped: '{}' has no /surface/cp", path)
                                  : std::string("surface Cp skipped: Cp is undefined when U = 0"));
  } else {
    plot_surface_cp(r, base + "_surface_cp.png", size);
    out.written.push_back(base + "_surface_cp.png");
  }
  if (out.written.empty()) {
    std::string why;
    for (const auto& s : out.skipped) why += (why.empty() ? "" : "; ") + s;
    throw std::runtime_error(fmt::format("nothing to plot in '{}': {}", path, why));
  }
  return out;
}

void command_plot(const std::string& path, const std::string& dir, const std::string& size, bool quiet) {
  const PlotSize sz = size.empty() ? PlotSize{} : parse_plot_size(size);
  const PlotOutcome o = plot_result_file(path, dir, sz);
  for (const auto& s : o.skipped) std::fprintf(stderr, "magnus: note: %s\n", s.c_str());
  if (!quiet)
    for (const auto& w : o.written) std::printf("%s\n", w.c_str());
}

}  // namespace magnus
