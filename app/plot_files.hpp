#pragma once
// `magnus plot FILE [-o DIR] [--size WxH]`: the pictures of a result file (streamlines, Cp field, surface
// Cp) or of a sweep file (C_L against α or Γ), rebuilt from the HDF5 alone. The files are read here
// (through io/) and their data handed to plot/, which builds the pictures and draws them.
#include <optional>
#include <string>
#include <vector>

#include "plot/figures.hpp"

namespace magnus {

/// "WxH" (e.g. 900x700), each 16 … 16384 pixels. Throws std::invalid_argument with one line.
PlotSize parse_plot_size(const std::string& text);

/// Reads a "magnus-sweep" file's /parameters and /sweep columns (alpha, circulation, cl) into a LiftSweep.
/// Throws std::runtime_error with one line.
LiftSweep read_lift_sweep(const std::string& path);

/// The pictures written by `magnus plot`, in order.
struct PlotOutcome {
  std::vector<std::string> written;  ///< PNG paths
  std::vector<std::string> skipped;  ///< one line each: which picture and why
};

/// A result file: dir/<stem>_streamlines.png, _cp.png and _surface_cp.png (a navier-stokes result adds
/// _vorticity.png, _forces.png: C_L, C_D against t, and _shear.png); a sweep file: dir/<stem>_cl.png
/// (stem: the file name without its extension; dir "" means the file's directory). A picture whose data
/// the file lacks is skipped; throws if nothing can be drawn.
/// `window`: the field pictures' window (units of a), default view_window. onset_files: magnus-stability
/// files with a 3D onset each, marked on the S(Re, α) map of a navier-stokes sweep (refused for any other).
PlotOutcome plot_result_file(const std::string& path, const std::string& dir, PlotSize size,
                             const std::optional<PlotWindow>& window = {},
                             const std::vector<std::string>& onset_files = {});

/// `magnus plot`: plot_result_file, the skipped pictures noted on stderr, the written ones on stdout;
/// window "" is the default (else parse_plot_window).
void command_plot(const std::string& path, const std::string& dir, const std::string& size,
                  const std::string& window, bool quiet, const std::vector<std::string>& onset_files = {});

}  // namespace magnus
