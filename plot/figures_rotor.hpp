#pragma once
// The rotor-sail data (postproc/rotor_data) on the lift-sweep figure: the datasets whose Reynolds number fits
// the scene's, as markers (tabulated) or dashed lines (fits), each named in the legend with its Re.
#include "plot/figures.hpp"
#include "postproc/rotor_data.hpp"

namespace magnus {

/// Adds to `f` each dataset of `data` that rotor_fits_reynolds(d, re) (re <= 0: no viscosity, all of them),
/// in magnus's sign (C_L = −|C_L|), clipped to α in [xlo, xhi]: points as hollow markers, a fit as a
/// dashed line sampled every Δα = (xhi − xlo)/100 inside its alpha_range. Returns how many were added.
int add_rotor_overlays(CurveFigure& f, const RotorData& data, double re, double xlo, double xhi);

}  // namespace magnus
