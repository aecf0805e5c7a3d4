// Interim: Bernoulli p = p∞ + ½ρ(U² − |u|²), wrong in the wake; the pressure Poisson solve replaces it.
#include "postproc/ns_pressure.hpp"
namespace magnus {
std::vector<double> ns_pressure_field(const PolarGrid& g, const NsParams& p, double rho, double p_inf,
                                      const NsState& s) {
  std::vector<double> ur, ut;
  ns_velocity(g, s.psi, ur, ut);
  std::vector<double> out(ur.size());
  for (size_t k = 0; k < out.size(); ++k) out[k] = p_inf + 0.5 * rho * (p.U * p.U - ur[k] * ur[k] - ut[k] * ut[k]);
  return out;
}
}
