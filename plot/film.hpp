#pragma once
// The frames of a wake film (`magnus plot RESULT --movie FILE`): for each stored snapshot of a navier-stokes
// result, the vorticity picture `magnus plot` draws (over one colour range for the whole film, the
// snapshot's time in its title) above the forces against time with that time marked. A frame is drawn as
// two PNGs, which the caller stacks into one image of the film (app/movie runs the encoder). Data in, no
// files read here.
#include <string>
#include <utility>

#include "plot/figures.hpp"

namespace magnus {

/// The film's colour range: vorticity_range pooled over every snapshot of r inside window w, so that the
/// colour bar (±limit, 1/s) is the same in every frame.
VorticityRange film_vorticity_range(const FlowResult& r, const PlotWindow& w);

/// "t = 123.45 D/U": time t (s) over the result's time unit D/U (U_ref = U, or a|ω| when U = 0); "t = 1.2 s"
/// when the result has none.
std::string film_time_label(const FlowResult& r, double t);

/// vorticity_field_picture of snapshot k over the film's range, the time stamp added to its title.
ContourFieldPicture film_vorticity_picture(const FlowResult& r, size_t k, const PlotWindow& w,
                                           const VorticityRange& range);

/// force_history_figure with time t (s) marked: a black line across the curves and dots on C_L(t) and
/// C_D(t) (linear between the history's samples); a short title, without potential flow's C_L.
CurveFigure film_force_figure(const FlowResult& r, double t);

/// The two panels of a frame of `size`: the vorticity on top (55% of the height, rounded to even pixels)
/// and the forces below (the rest), both the frame's width.
std::pair<PlotSize, PlotSize> film_panel_sizes(PlotSize size);

/// Draws frame k of the film: the vorticity panel to top_png, the forces panel to bottom_png (sizes from
/// film_panel_sizes). Returns where the vorticity panel was drawn (its colour bar).
PlotFrame draw_film_frame(const FlowResult& r, size_t k, const PlotWindow& w, const VorticityRange& range,
                          PlotSize size, const std::string& top_png, const std::string& bottom_png);

}  // namespace magnus
