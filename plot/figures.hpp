#pragma once
// `magnus plot FILE [-o DIR] [--size WxH]`: the pictures of a result file, rebuilt from the HDF5 alone.
#include <string>
#include <vector>

#include "plot/plot.hpp"

namespace magnus {

/// "WxH" (e.g. 900x700), each 16 … 16384 pixels. Throws std::invalid_argument with one line.
PlotSize parse_plot_size(const std::string& text);

/// The pictures written by `magnus plot`, in order: streamlines, Cp field, surface Cp.
struct PlotOutcome {
  std::vector<std::string> written;  ///< PNG paths
  std::vector<std::string> skipped;  ///< one line each: which picture and why
};

/// Write dir/<stem>_streamlines.png, _cp.png and _surface_cp.png (stem: the file name without its
/// extension; dir "" means the result's directory). A picture whose data the file lacks is skipped;
/// throws if nothing can be drawn.
PlotOutcome plot_result_file(const std::string& path, const std::string& dir, PlotSize size);

/// `magnus plot`: plot_result_file, the skipped pictures noted on stderr, the written ones on stdout.
void command_plot(const std::string& path, const std::string& dir, const std::string& size, bool quiet);

}  // namespace magnus
