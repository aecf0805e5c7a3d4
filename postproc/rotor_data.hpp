#pragma once
// Published rotor-sail (Flettner rotor) lift and drag against spin ratio (read from data/rotor_data.toml
// by io/rotor_data): experiments, CFD and a full-scale fit, each with its citation, Reynolds number and
// aspect ratio; which of them fit a scene's Reynolds number; and the text that sets them beside the ideal
// and the 2D model.
#include <optional>
#include <string>
#include <vector>

namespace magnus {

/// One tabulated point; C_L in magnus's sign (CCW spin, flow towards +x: C_L < 0 for α > 0).
struct RotorPoint {
  double alpha = 0.0;        ///< spin ratio aω/U
  double cl = 0.0;           ///< lift coefficient L/(½ρU²·D·h), magnus's sign
  std::optional<double> cd;  ///< drag coefficient D/(½ρU²·D·h)
};

/// One publication's rotor data: points or a polynomial fit.
struct RotorDataset {
  std::string id;        ///< short key, e.g. "tillig2020"
  std::string label;     ///< legend text
  std::string citation;  ///< authors, title, journal, volume, year
  std::string source;    ///< where in the publication, and the copy the numbers were read from
  std::string method;    ///< "experiment", "CFD" or "fit"
  std::string accuracy;  ///< tabulated / digitised ± / fit
  bool reynolds_known = false;
  double reynolds_min = 0.0, reynolds_max = 0.0;  ///< Re = U·D/ν (equal for a single value)
  std::string reynolds_note;                      ///< where the Re comes from
  bool three_d = true;                            ///< "3D" rotor, else a 2D section (infinite span)
  std::optional<double> aspect_ratio;             ///< h/D when stated
  std::string end_plates;                         ///< in words
  double alpha_min = 0.0, alpha_max = 0.0;        ///< where the data (or the fit) hold
  std::vector<RotorPoint> points;                 ///< tabulated data (empty for a fit)
  std::vector<double> cl_poly, cd_poly;  ///< fit: |C_L|(α) = Σ c_k α^k, C_D(α) likewise (ascending)
};

struct RotorData {
  std::string title;
  std::string sign_convention;
  std::vector<RotorDataset> datasets;
};

/// Σ c_k α^k (Horner); 0 for no coefficients.
double polynomial_value(const std::vector<double>& c, double alpha);

/// The dataset's lift (magnus's sign) and drag at α: a fit evaluated, tabulated data interpolated
/// linearly; nullopt outside [alpha_min, alpha_max] (or, for drag, when none is given).
std::optional<RotorPoint> rotor_value(const RotorDataset& d, double alpha);

/// The rule for drawing a dataset beside a scene: a scene with a Reynolds number (re > 0) fits a dataset
/// whose Re range overlaps [re/3, 3·re]; a dataset whose Re is unknown fits no such scene. A scene
/// without a viscosity (re <= 0: potential flow has no Re) fits every dataset: each is labelled with its Re.
bool rotor_fits_reynolds(const RotorDataset& d, double re);

/// "Re = 3.6·10^5", "Re = 1·10^6 … 7·10^6" or "Re not stated".
std::string rotor_reynolds_text(const RotorDataset& d);

/// A text block for a scene (re <= 0: no viscosity given; aspect_ratio <= 0: 2D, per unit span): the
/// ideal (potential flow, C_L = −2πα: the inviscid upper bound), the 2D laminar Navier–Stokes model
/// (good for Re ≲ 200 only), and each rotor dataset's |C_L|, C_D at α with its Re, geometry and end
/// plates, marked whether its Re fits the scene's.
std::string rotor_comparison_text(const RotorData& data, double re, double alpha, double aspect_ratio);

}  // namespace magnus
