#pragma once
// The summary lines about the scene in the world (flow direction, a rotor sail's course, the span's totals)
// and about what potential flow's answer means for a real cylinder (the Reynolds number, the inviscid bound,
// the nearest published viscous figure). Shared by both models' summaries.
#include <optional>
#include <string>

#include "physics/reference_data.hpp"
#include "postproc/result.hpp"

namespace magnus {

/// The published viscous point nearest a scene: the tabulated |α| nearest the scene's |α| = a|ω|/U (within
/// kReferenceAlphaReach), of the dataset whose Re is nearest in log(Re) when the scene has one; C_L signed
/// for the scene's spin (C_L(−α) = −C_L(α)).
struct NearestReference {
  double alpha = 0.0;     ///< the tabulated spin ratio (signed as the scene's)
  double reynolds = 0.0;  ///< the Re it holds for
  double cl = 0.0;        ///< C_L, magnus's sign
  std::string label, source;
};

/// How far from a tabulated α a reference point is still "the nearest" one (the tables' step is 0.5).
constexpr double kReferenceAlphaReach = 0.25;

/// The nearest reference point of ref for sc; empty when U = 0 or no point is within reach.
std::optional<NearestReference> nearest_reference(const Scene& sc, const ViscousReference& ref);

/// The shipped viscous reference (data/viscous_lift_reference.toml), read once; empty if it cannot be read
/// (the summary then says so rather than failing the run).
const ViscousReference* shipped_reference();

/// One summary line: the label in 15 columns, then the text ("{:<15}{}\n").
std::string summary_line(const std::string& label, const std::string& text);

/// "272031 N (272 kN)": a total force, with kN or MN beside N when it is that large.
std::string newtons(double v, const char* unit = "N");

/// The world lines of a summary (each "{:<15}{}\n"): "direction" when the flow is turned, "course" with the
/// thrust and side force per metre, "span" with the totals in N (and torque, spin power for navier-stokes).
/// Empty for a scene with none of these keys. The navier-stokes summary calls it after its forces.
std::string scene_lines(const FlowResult& r);

/// "Reynolds" when a viscosity is given (potential flow: reported, not used); "" otherwise.
std::string reynolds_line(const Scene& sc);

/// Potential flow's "ideal" lines: it is the inviscid upper bound, with the nearest published viscous C_L
/// and the Re it holds for (or why there is none); "" when U = 0.
std::string inviscid_bound_lines(const FlowResult& r);

/// A rotor (a scene with cylinder.span): the ideal, the 2D viscous model and the published rotor data at the
/// scene's α side by side, with what each is good for (rotor_comparison_text, aspect ratio span/D); "" without
/// a span or with U = 0.
std::string rotor_lines(const Scene& sc);

}  // namespace magnus
