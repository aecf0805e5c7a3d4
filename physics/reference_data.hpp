#pragma once
// Published viscous lift on a rotating cylinder: the data structures (the values themselves are in
// data/viscous_lift_reference.toml, read by io/reference_file). Shown beside the potential-flow results
// so that users see where real flow departs from the ideal.
#include <optional>
#include <string>
#include <vector>

namespace magnus {

/// One tabulated point; C_L in magnus's sign (CCW spin, flow towards +x: C_L < 0 for α > 0).
struct ReferencePoint {
  double alpha = 0.0;        ///< spin ratio aω/U
  double cl = 0.0;           ///< lift coefficient, magnus's sign
  std::optional<double> cd;  ///< drag coefficient
};

/// One publication's table.
struct ViscousDataset {
  std::string id;         ///< short key, e.g. "stojkovic2002"
  std::string label;      ///< legend text, e.g. "viscous, Re = 100 (Stojković et al. 2002)"
  std::string citation;   ///< authors, title, journal, volume, pages, year
  std::string source;     ///< where in the publication, e.g. "Table II"
  std::string method;     ///< how the values were obtained
  double reynolds = 0.0;  ///< Re = U·2a/ν
  std::string cl_sign;    ///< as tabulated: "magnitude" (|C_L|) or "magnus" (already our sign)
  std::vector<ReferencePoint> points;
};

struct ViscousReference {
  std::string title;
  std::string sign_convention;  ///< how the tabulated signs map onto magnus's
  std::vector<ViscousDataset> datasets;
};

}  // namespace magnus
