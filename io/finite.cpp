#include "io/finite.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "io/schema.hpp"

namespace magnus {

std::string first_non_finite(const FlowResult& r) {
  for (const AttrSpec& a : result_attributes()) {
    if (!a.number || !applies(a.models, r)) continue;
    const std::optional<double> v = a.number(r);
    if (v && !std::isfinite(*v)) return fmt::format("{} ({}@{})", a.description, a.group, a.name);
  }
  const size_t n_theta = size_t(r.grid.n_theta);
  for (const DatasetSpec& d : result_datasets()) {
    if (!applies(d.models, r)) continue;
    const std::vector<double> v = d.values(r);
    for (size_t q = 0; q < v.size(); ++q) {
      if (std::isfinite(v[q])) continue;
      if (d.shape == DataShape::grid && n_theta > 0)
        return fmt::format("{} at (i, j) = ({}, {})", d.path, q / n_theta, q % n_theta);
      return fmt::format("{} at {}", d.path, q);
    }
  }
  return "";
}

void check_finite(const FlowResult& r) {
  const std::string what = first_non_finite(r);
  if (!what.empty())
    throw std::runtime_error(fmt::format(
        "{} is not finite (NaN or infinite: the inputs are beyond double precision); nothing was written",
        what));
}

}  // namespace magnus
