#pragma once
// PNG figures with PLplot (pngcairo, headless): streamlines, the Cp field, surface Cp, lift
// against spin ratio, and speed against error. Every file appears only when complete
// (written beside the target under a temporary name, then renamed); any failure throws
// std::runtime_error naming the file and leaves no file behind. Calls are serialised
// (PLplot keeps global state), so the functions may be called from several threads.
#include <string>
#include <vector>
#include "postproc/result.hpp"

namespace magnus {

/// Image size in pixels.
struct PlotSize {
  int width = 1000, height = 800;
};

/// Streamlines: ψ contours (m²/s) on the polar grid closed over θ = 0, body filled, numeric (dots) and exact (rings) stagnation points, x, y in m, window |x|, |y| ≤ min(R, 4a).
void plot_streamlines(const FlowResult& r, const std::string& png, PlotSize size = {});

/// Cp field (dimensionless) as filled contours with a colour bar over x, y in m, same window as the streamlines; throws if r.fields.cp is empty.
void plot_cp_field(const FlowResult& r, const std::string& png, PlotSize size = {});

/// Surface Cp(θ), θ in degrees 0…360: numeric nodes (points) against the exact 1 − (α − 2 sinθ)² (line); throws when Cp is undefined (U = 0).
void plot_surface_cp(const FlowResult& r, const std::string& png, PlotSize size = {});

/// One (x, y) data point of a curve.
struct CurvePoint {
  double x, y;
};
/// Reference data (e.g. viscous measurements) drawn as labelled points.
struct ReferenceSet {
  std::string label;
  std::vector<CurvePoint> points;
};

/// C_L against spin ratio α = aω/U: numeric points, Kutta–Joukowski −2πα, seed estimate −4α, Prandtl's bound |C_L| = 4π (α = 2 marked), reference sets with a legend label each.
/// xlabel replaces the x-axis label when not empty (e.g. the equivalent spin ratio Γ/(2πaU) of a circulation sweep).
void plot_sweep(const std::string& title, const std::vector<CurvePoint>& numeric,
                const std::vector<ReferenceSet>& references, const std::string& png, PlotSize size = {},
                const std::string& xlabel = {});

/// One labelled series of a log-log plot (e.g. one method and stencil).
struct Series {
  std::string label;
  std::vector<CurvePoint> points;
};

/// Log-log plot (e.g. error against time, the Pareto front): a line with markers per series; non-positive values are skipped, throws if nothing is left.
void plot_loglog(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                 const std::vector<Series>& series, const std::string& png, PlotSize size = {});

}  // namespace magnus
