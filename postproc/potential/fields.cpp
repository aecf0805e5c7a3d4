#include "postproc/potential/fields.hpp"

#include <cmath>
#include <stdexcept>

#include "mesh/fd_weights.hpp"
#include "physics/exact.hpp"

namespace magnus {

namespace {
size_t field_index(const std::string& name) {
  const auto& n = field_names();
  for (size_t k = 0; k < n.size(); ++k)
    if (n[k] == name) return k;
  throw std::invalid_argument("unknown field '" + name + "'");
}
}  // namespace

bool FieldSelection::has(const std::string& name) const { return on[field_index(name)]; }

bool FieldSelection::any_velocity() const {
  for (const char* f : {"u_r", "u_theta", "u_x", "u_y", "pressure", "cp"})
    if (has(f)) return true;
  return false;
}

FieldSelection select_fields(const std::optional<std::vector<std::string>>& names, FlowModel model) {
  FieldSelection s;
  if (!names) {
    for (size_t k = 0; k < s.on.size(); ++k) s.on[k] = field_of_model(field_names()[k], model);
    return s;
  }
  s.on.assign(field_names().size(), false);
  for (const auto& n : *names) s.on[field_index(n)] = true;
  return s;
}

const std::vector<double>& Fields::get(const std::string& name) const {
  const std::vector<double>* all[] = {&psi,      &u_r, &u_theta,   &u_x,       &u_y,
                                      &pressure, &cp,  &psi_exact, &psi_error, &vorticity};
  return *all[field_index(name)];
}

std::vector<double>& Fields::get(const std::string& name) {
  return const_cast<std::vector<double>&>(static_cast<const Fields&>(*this).get(name));
}

int derivative_order(StencilKind stencil) { return stencil == StencilKind::nine_point ? 6 : 2; }

namespace {

/// ∂ψ/∂ξ on ring i at every column, into out (n_θ).
void d_dxi(const PolarGrid& g, const RadialDerivative& D, const std::vector<double>& psi, int i,
           double* out) {
  const int n = g.n_theta;
  std::fill(out, out + n, 0.0);
  const std::vector<double>& w = D.weights[i];
  for (size_t m = 0; m < w.size(); ++m) {
    const double* row = &psi[size_t(D.first[i] + m) * n];
    for (int j = 0; j < n; ++j) out[j] += w[m] * row[j];
  }
}

}  // namespace

Fields compute_fields(const PolarGrid& g, const Scene& scene, const std::vector<double>& psi,
                      const std::vector<double>& psi_exact, const FieldSelection& sel, int order) {
  Fields f;
  const int n = g.n_theta;
  const size_t N = size_t(g.nodes());
  if (sel.has("psi")) f.psi = psi;
  if (sel.has("psi_exact")) f.psi_exact = psi_exact;
  if (sel.has("psi_error")) {
    f.psi_error.resize(N);
    for (size_t q = 0; q < N; ++q) f.psi_error[q] = psi[q] - psi_exact[q];
  }
  if (!sel.any_velocity()) return f;
  const RadialDerivative D = radial_derivative(g.xi, order, order > 2);
  const std::vector<double> cw = periodic_derivative(g.d_theta, order);
  std::vector<double> ur(N), ut(N);
  std::vector<double> cs(n), sn(n);
  for (int j = 0; j < n; ++j) {
    cs[j] = std::cos(g.theta[j]);
    sn[j] = std::sin(g.theta[j]);
  }
  for (int i = 0; i < g.n_r; ++i) {
    const double inv_r = 1.0 / g.r[i];
    double* uti = &ut[size_t(i) * n];
    d_dxi(g, D, psi, i, uti);
    const double* row = &psi[size_t(i) * n];
    double* uri = &ur[size_t(i) * n];
    for (int j = 0; j < n; ++j) {
      double d = 0.0;
      for (size_t m = 0; m < cw.size(); ++m) d += cw[m] * (row[(j + m + 1) % n] - row[(j + n - (m + 1)) % n]);
      uri[j] = d * inv_r;  // u_r = (1/r) ∂ψ/∂θ
      uti[j] *= -inv_r;    // u_θ = −∂ψ/∂r = −(1/r) ∂ψ/∂ξ
    }
  }
  const double U2 = scene.speed * scene.speed, half_rho = 0.5 * scene.density;
  if (sel.has("u_x") || sel.has("u_y")) {
    if (sel.has("u_x")) f.u_x.resize(N);
    if (sel.has("u_y")) f.u_y.resize(N);
    for (size_t q = 0; q < N; ++q) {
      const int j = int(q % n);
      if (!f.u_x.empty()) f.u_x[q] = ur[q] * cs[j] - ut[q] * sn[j];
      if (!f.u_y.empty()) f.u_y[q] = ur[q] * sn[j] + ut[q] * cs[j];
    }
  }
  if (sel.has("pressure")) {
    f.pressure.resize(N);
    for (size_t q = 0; q < N; ++q)
      f.pressure[q] = scene.pressure_inf + half_rho * (U2 - ur[q] * ur[q] - ut[q] * ut[q]);
  }
  if (sel.has("cp") && scene.speed > 0.0) {
    f.cp.resize(N);
    for (size_t q = 0; q < N; ++q) f.cp[q] = 1.0 - (ur[q] * ur[q] + ut[q] * ut[q]) / U2;
  }
  if (sel.has("u_r")) f.u_r = std::move(ur);
  if (sel.has("u_theta")) f.u_theta = std::move(ut);
  return f;
}

std::vector<double> surface_u_theta(const PolarGrid& g, const std::vector<double>& psi, int order) {
  const RadialDerivative D = radial_derivative(g.xi, order, order > 2);
  std::vector<double> u(g.n_theta);
  d_dxi(g, D, psi, 0, u.data());
  for (double& v : u) v *= -1.0 / g.a;
  return u;
}

namespace {
double mean_of(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m += x;
  return m / double(v.size());
}

Surface surface_from_split(const PolarGrid& g, const Scene& scene, double mean, std::vector<double> fluct) {
  const int n = g.n_theta;
  Surface s;
  s.theta = g.theta;
  s.u_mean = mean;
  s.u_theta.resize(n);
  for (int j = 0; j < n; ++j) s.u_theta[j] = mean + fluct[j];
  s.u_fluct = std::move(fluct);
  const double U2 = scene.speed * scene.speed;
  s.pressure.resize(n);
  for (int j = 0; j < n; ++j)
    s.pressure[j] = scene.pressure_inf + 0.5 * scene.density * (U2 - s.u_theta[j] * s.u_theta[j]);
  if (scene.speed > 0.0) {
    const ExactFlow ex = exact_flow(scene);
    s.cp.resize(n);
    s.cp_exact.resize(n);
    for (int j = 0; j < n; ++j) {
      s.cp[j] = 1.0 - s.u_theta[j] * s.u_theta[j] / U2;
      s.cp_exact[j] = ex.cp(g.a, g.theta[j]);
    }
  }
  return s;
}
}  // namespace

Surface surface_from_u_theta(const PolarGrid& g, const Scene& scene, std::vector<double> u_theta) {
  const double m = mean_of(u_theta);
  for (double& u : u_theta) u -= m;
  return surface_from_split(g, scene, m, std::move(u_theta));
}

Surface surface_from_basis(const PolarGrid& g, const Scene& scene, const std::vector<double>& s_U,
                           const std::vector<double>& s_Gamma) {
  const double U = scene.speed, Gamma = scene.Gamma(), mU = mean_of(s_U);
  std::vector<double> fluct(s_U.size());
  for (size_t j = 0; j < s_U.size(); ++j) fluct[j] = U * (s_U[j] - mU);
  return surface_from_split(g, scene, U * mU + Gamma * mean_of(s_Gamma), std::move(fluct));
}

Surface compute_surface(const PolarGrid& g, const Scene& scene, const std::vector<double>& psi, int order) {
  return surface_from_u_theta(g, scene, surface_u_theta(g, psi, order));
}

double periodic_interpolate(const std::vector<double>& f, double theta) {
  const int n = int(f.size());
  const double h = 2.0 * M_PI / n;
  const double x = theta / h;
  const long j0 = long(std::floor(x));
  const double t = x - j0;
  // Lagrange weights for nodes −1, 0, 1, 2 at t.
  const double w[4] = {-t * (t - 1) * (t - 2) / 6, (t + 1) * (t - 1) * (t - 2) / 2,
                       -(t + 1) * t * (t - 2) / 2, (t + 1) * t * (t - 1) / 6};
  double v = 0.0;
  for (int m = 0; m < 4; ++m) v += w[m] * f[size_t(((j0 - 1 + m) % n + n) % n)];
  return v;
}

std::vector<double> u_theta_on_ray(const PolarGrid& g, const std::vector<double>& psi, double theta,
                                   int order) {
  const RadialDerivative D = radial_derivative(g.xi, order, order > 2);
  std::vector<double> out(g.n_r), ring(g.n_theta);
  for (int i = 0; i < g.n_r; ++i) {
    d_dxi(g, D, psi, i, ring.data());
    out[i] = -periodic_interpolate(ring, theta) / g.r[i];
  }
  return out;
}

}  // namespace magnus
