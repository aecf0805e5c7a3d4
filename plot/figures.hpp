#pragma once
// The pictures of a result (streamlines, Cp field, surface Cp; a navier-stokes result's vorticity, forces
// against time and wall shear) and of a lift sweep (C_L against α or Γ), built from the data (FlowResult,
// LiftSweep; app/plot_files reads them from files). This is where the physics meets the plots: the exact
// curves, the models and the windows are built here from physics/ and handed to the plot functions,
// which only draw.
#include <optional>
#include <string>
#include <vector>

#include "physics/reference_data.hpp"
#include "physics/scene.hpp"
#include "plot/curves.hpp"
#include "plot/field_plots.hpp"
#include "postproc/result.hpp"
#include "postproc/rotor_data.hpp"

namespace magnus {

/// A curve plot ready to draw: its page, lines and point sets.
struct CurveFigure {
  CurvePage page;
  std::vector<LineCurve> lines;
  std::vector<PointSet> points;
};

/// Half-width of a result's view window in units of a: min(R, 4a), widened to min(R, 1.2 r_s) to show
/// a free stagnation point at r_s.
double view_half_width(const FlowResult& r);

/// The default window of a result's field pictures (units of a, wind frame): the square of
/// view_half_width; for an unsteady navier-stokes result the wake, x/a in [−5, 25] and y/a in [−6, 6]
/// (each clipped to R/a).
PlotWindow view_window(const FlowResult& r);

/// "X0:X1,Y0:Y1" in units of the radius (e.g. -5:25,-6:6): finite, X0 < X1, Y0 < Y1, within ±10⁶, width
/// over height 1/20 to 20. Throws std::invalid_argument with one line.
PlotWindow parse_plot_window(const std::string& text);

/// The window asked for (checked to reach the grid, r < R; std::invalid_argument otherwise), or the
/// default view_window.
PlotWindow window_for(const FlowResult& r, const std::optional<PlotWindow>& asked);

/// Streamlines of a result in x/a, y/a: ψ, the numeric and exact stagnation points inside the window
/// (a point outside it becomes a legend note), the separatrix through a free stagnation point.
StreamlinePicture streamline_picture(const FlowResult& r, const std::optional<PlotWindow>& window = {});

/// The Cp field of a result in x/a, y/a, colours over the field's range in the window. Throws
/// std::runtime_error when the result has no Cp field.
ContourFieldPicture cp_picture(const FlowResult& r, const std::optional<PlotWindow>& window = {});

/// The vorticity field of a navier-stokes result in x/a, y/a: a diverging map over symmetric limits (±the
/// 98th percentile of |ζ| in the window, so that the wake is not washed out by the wall's peak; beyond it
/// the end colours; |ζ| below limit/41 is white, the zero colour), the body drawn. Throws
/// std::runtime_error when the result has no vorticity field.
ContourFieldPicture vorticity_picture(const FlowResult& r, const std::optional<PlotWindow>& window = {});

/// |ζ| (1/s) over the nodes of grid g inside window w (units of a), pooled over one or more fields of g:
/// its 98th percentile (vorticity_picture's colour limit) and its peak.
struct VorticityRange {
  double limit = 0.0, peak = 0.0;
};
VorticityRange vorticity_range(const PolarGrid& g, const std::vector<const std::vector<double>*>& fields,
                               const PlotWindow& w);

/// vorticity_picture of a vorticity field zeta (1/s) on r's grid (e.g. a stored snapshot's), coloured over
/// ±range.limit when a range is given (one range for several pictures), else over its own.
ContourFieldPicture vorticity_field_picture(const FlowResult& r, const std::vector<double>& zeta,
                                            const std::optional<PlotWindow>& window,
                                            const std::optional<VorticityRange>& range);

/// C_L(t) and C_D(t) of a navier-stokes result's force history against t in D/U, with their means (over
/// the last period) and potential flow's C_L for the same scene. Throws std::runtime_error when the
/// result has no history.
CurveFigure force_history_figure(const FlowResult& r);

/// The wall shear stress τ_w(θ) of a navier-stokes result, θ in degrees, with the separation points
/// (τ_w = 0). Throws std::runtime_error when the result has none.
CurveFigure shear_stress_figure(const FlowResult& r);

/// Surface Cp(θ), θ in degrees (for a navier-stokes result: its Cp against potential flow's): the numeric
/// nodes against the exact curve from ExactFlow (the given circulation or the spin's). Throws
/// std::runtime_error when Cp is undefined (U = 0) or missing.
CurveFigure surface_cp_figure(const FlowResult& r);

/// The numbers of a lift sweep, as `magnus sweep` computes them or a sweep file stores them.
struct LiftSweep {
  bool by_circulation = false;  ///< x is Γ (m²/s) instead of the spin ratio α
  std::vector<double> x;        ///< α, or Γ in m²/s
  std::vector<double> cl;       ///< numeric C_L at each x
  Scene base;                   ///< radius, speed, and (circulation sweep) the constant spin
  std::string title;            ///< the case's title (shown literally)
  int n_theta = 0, n_r = 0;     ///< the grid, for the title (0: not shown)
};

/// C_L against α (or Γ): numeric points, Kutta–Joukowski, the seed estimate (−4α; in a circulation sweep
/// the constant −4aω/U of the fixed spin, omitted when ω = 0), Prandtl's bound |C_L| = 4π where the
/// stagnation points merge, and the viscous reference data (spin sweeps only; may be null) whose Re is
/// within a factor 3 of the scene's (all of them when it has no Re; each label names its Re). Spin sweeps also draw
/// the rotor-sail data (may be null) that fit the scene's Re = U·2a/ν (base.viscosity > 0; without a
/// viscosity there is no Re and all are drawn): see add_rotor_overlays.
CurveFigure lift_figure(const LiftSweep& s, const ViscousReference* reference,
                        const RotorData* rotor = nullptr);

}  // namespace magnus
