#include "postproc/rotor_data.hpp"

#include <fmt/core.h>

#include <cmath>

#include "physics/checked_cast.hpp"

namespace magnus {

namespace {

/// v as "m·10^e": m whole when it is, else two significant digits.
std::string sci(double v) {
  const int e = saturate_cast<int>(std::floor(std::log10(v)));
  const double m = v / std::pow(10.0, e);
  return std::fabs(m - std::round(m)) < 1e-9 ? fmt::format("{:.0f}·10^{}", m, e)
                                             : fmt::format("{:.2g}·10^{}", m, e);
}

}  // namespace

double polynomial_value(const std::vector<double>& c, double alpha) {
  double v = 0.0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * alpha + *it;
  return v;
}

std::optional<RotorPoint> rotor_value(const RotorDataset& d, double alpha) {
  if (!(alpha >= d.alpha_min - 1e-12 && alpha <= d.alpha_max + 1e-12)) return std::nullopt;
  RotorPoint p;
  p.alpha = alpha;
  if (!d.cl_poly.empty()) {
    p.cl = -polynomial_value(d.cl_poly, alpha) + 0.0;
    if (!d.cd_poly.empty()) p.cd = polynomial_value(d.cd_poly, alpha);
    return p;
  }
  const auto& q = d.points;
  if (alpha < q.front().alpha || alpha > q.back().alpha) return std::nullopt;  // no extrapolation
  size_t j = 0;
  while (j + 1 < q.size() && q[j + 1].alpha < alpha) ++j;
  if (j + 1 == q.size()) return q.back();
  const double w = (alpha - q[j].alpha) / (q[j + 1].alpha - q[j].alpha);
  p.cl = q[j].cl + w * (q[j + 1].cl - q[j].cl);
  if (q[j].cd && q[j + 1].cd) p.cd = *q[j].cd + w * (*q[j + 1].cd - *q[j].cd);
  return p;
}

bool rotor_fits_reynolds(const RotorDataset& d, double re) {
  if (!(re > 0.0) || !std::isfinite(re)) return true;
  if (!d.reynolds_known) return false;
  return d.reynolds_max >= re / 3.0 && d.reynolds_min <= 3.0 * re;
}

std::string rotor_reynolds_text(const RotorDataset& d) {
  if (!d.reynolds_known) return "Re not stated";
  if (d.reynolds_min == d.reynolds_max) return "Re = " + sci(d.reynolds_min);
  return fmt::format("Re = {} … {}", sci(d.reynolds_min), sci(d.reynolds_max));
}

std::string rotor_comparison_text(const RotorData& data, double re, double alpha, double aspect_ratio) {
  const bool has_re = re > 0.0 && std::isfinite(re);
  std::string out = "ideal vs viscous-2D vs rotor data";
  out += fmt::format(" (scene: α = {:.3g}, {}, {})\n", alpha,
                     has_re ? "Re = " + sci(re) : "no viscosity given: no Re",
                     aspect_ratio > 0.0 ? fmt::format("aspect ratio h/D = {:.3g}", aspect_ratio)
                                        : std::string("2D, per unit span"));
  out += fmt::format(
      "  {:<24}|C_L| = 2πα = {:.3g}, C_D = 0: the inviscid upper bound (no boundary layer, no "
      "wake, no tip losses)\n",
      "ideal (potential flow)", 2.0 * M_PI * std::fabs(alpha));
  out += fmt::format(
      "  {:<24}2D laminar Navier–Stokes: good for Re ≲ 200 only{}\n", "viscous 2D",
      has_re ? (re <= 200.0 ? " (this scene's Re is in range)"
                            : " (this scene's Re is above it: real flow there is turbulent and 3D)")
             : "");
  out += fmt::format(
      "  {:<24}3D rotors with end plates and tip losses, or 2D sections at high Re; each holds "
      "for its own Re{}:\n",
      "rotor data", has_re ? " (✓: within a factor 3 of this scene's)" : "");
  for (const auto& d : data.datasets) {
    const auto v = rotor_value(d, std::fabs(alpha));
    std::string values =
        v ? fmt::format("|C_L| = {:.3g}", std::fabs(v->cl)) : std::string("α outside its range");
    if (v && v->cd) values += fmt::format(", C_D = {:.3g}", *v->cd);
    const std::string geometry = d.three_d
                                     ? (d.aspect_ratio ? fmt::format("3D, h/D = {:.3g}", *d.aspect_ratio)
                                                       : std::string("3D, h/D not stated"))
                                     : std::string("2D");
    out += fmt::format("  {} {:<22}{}; {}, {}, {}, {}; α from {} to {}\n",
                       has_re ? (rotor_fits_reynolds(d, re) ? "✓" : " ") : "-", d.id, values, d.method,
                       rotor_reynolds_text(d), geometry, "end plates: " + d.end_plates, d.alpha_min,
                       d.alpha_max);
  }
  return out;
}

}  // namespace magnus
