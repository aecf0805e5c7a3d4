#pragma once
// Published viscous lift on a rotating cylinder (data/viscous_lift_reference.toml), shown beside the
// potential-flow results so that users see where real flow departs from it.
#include <optional>
#include <string>
#include <vector>

namespace magnus {

/// One tabulated point; C_L in magnus's sign (CCW spin, flow towards +x: C_L < 0 for α > 0).
struct ReferencePoint {
  double alpha = 0.0;          ///< spin ratio aω/U
  double cl = 0.0;             ///< lift coefficient, magnus's sign
  std::optional<double> cd;    ///< drag coefficient
};

/// One publication's table.
struct ViscousDataset {
  std::string id;              ///< short key, e.g. "stojkovic2002"
  std::string label;           ///< legend text, e.g. "viscous, Re = 100 (Stojković et al. 2002)"
  std::string citation;        ///< authors, title, journal, volume, pages, year
  std::string source;          ///< where in the publication, e.g. "Table II"
  std::string method;          ///< how the values were obtained
  double reynolds = 0.0;       ///< Re = U·2a/ν
  std::string cl_sign;         ///< as tabulated: "magnitude" (|C_L|) or "magnus" (already our sign)
  std::vector<ReferencePoint> points;
};

struct ViscousReference {
  std::string title;
  std::string sign_convention;  ///< how the tabulated signs map onto magnus's
  std::vector<ViscousDataset> datasets;
};

/// Parse the reference file's TOML text; `origin` names it in messages. Every dataset must carry a
/// citation, a label, a Reynolds number and matching alpha/cl(/cd) arrays. Throws std::runtime_error
/// with one line.
ViscousReference parse_viscous_reference(const std::string& toml_text, const std::string& origin);

/// Read and parse a reference file. Throws std::runtime_error with one line.
ViscousReference load_viscous_reference(const std::string& path);

/// The data directory: $MAGNUS_DATA_DIR if set and non-empty, else the source tree's data/ (compile
/// definition MAGNUS_DATA_DIR).
std::string data_dir();

/// data_dir() + "/viscous_lift_reference.toml".
std::string viscous_reference_path();

}  // namespace magnus
