#pragma once
// `magnus plot RESULT --movie FILE [--fps N] [--size WxH] [--window …]`: the wake as a film. The stored
// snapshots of a navier-stokes result (output.snapshots = N) become its frames (plot/film draws each as
// PNGs in a private temporary directory), which ffmpeg encodes to FILE (.mp4: H.264; .gif), written
// under a temporary name beside it and renamed when complete.
#include <optional>
#include <string>

#include "plot/field_plots.hpp"
#include "plot/figures.hpp"

namespace magnus {

/// What a film holds.
struct MovieOutcome {
  size_t frames = 0;         ///< one per snapshot
  PlotSize size;             ///< each frame's size in pixels
  VorticityRange range;      ///< the one colour range of every frame (±range.limit, 1/s)
  PlotWindow window;         ///< the field window (units of a)
  PlotFrame vorticity;       ///< where the vorticity panel (the top of each frame) was drawn
};

/// Films at 1 … 120 frames a second.
constexpr int kMaxFps = 120;
/// The smallest frame whose two panels have room for their axes, labels and legend.
constexpr PlotSize kMinFilmSize{320, 256};

/// Makes the film `movie` (.mp4 or .gif) of the result file `path`'s snapshots. Refuses, with one line and
/// nothing written, a file that is not a navier-stokes result with snapshots and a force history, another
/// extension, fps outside 1 … kMaxFps, a size under kMinFilmSize or odd for .mp4, a missing ffmpeg, and a target that may not
/// be replaced (base/atomic_file). SIGINT or SIGTERM stops it at the next frame (or when ffmpeg ends),
/// with nothing left behind, by throwing Interrupted.
MovieOutcome make_movie(const std::string& path, const std::string& movie, PlotSize size,
                        const std::optional<PlotWindow>& window, int fps);

}  // namespace magnus
