// _magnus._stability: the navier-stokes steady state's leading eigenvalues and, given spanwise wavenumbers,
// its three-dimensional stability (magnus stability CASE --spanwise); _magnus._onset_3d: where the flow turns
// three-dimensional (--spanwise --critical-reynolds): numpy arrays and plain values.
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <fmt/core.h>

#include <cmath>
#include <complex>
#include <stdexcept>

#include "postproc/navier_stokes/resolution.hpp"
#include "postproc/navier_stokes/run.hpp"
#include "postproc/navier_stokes/spanwise_critical.hpp"
#include "postproc/navier_stokes/spanwise_scan.hpp"
#include "bindings.hpp"

namespace magnus::python {

namespace {

py::array_t<std::complex<double>> complex_array(const std::vector<std::complex<double>>& v) {
  py::array_t<std::complex<double>> a(py::ssize_t(v.size()));
  auto m = a.mutable_unchecked<1>();
  for (size_t k = 0; k < v.size(); ++k) m(py::ssize_t(k)) = v[k];
  return a;
}

/// The scan as columns over β·D; a wavenumber whose eigenvalue did not converge is NaN on its way to
/// python/magnus/__init__.py, which masks it.
py::dict scan_dict(const SpanwiseScan& s) {
  std::vector<double> beta, growth, frequency;
  std::vector<std::complex<double>> mu;
  for (const SpanwisePoint& pt : s.points) {
    beta.push_back(pt.beta_D);
    growth.push_back(pt.found ? pt.lambda.real() : NAN);
    frequency.push_back(pt.found ? pt.lambda.imag() : NAN);
    mu.push_back(pt.found ? pt.multiplier : std::complex<double>(NAN, NAN));
  }
  py::dict d;
  d["base"] = s.periodic ? "periodic" : "steady";
  const py::ssize_t n = py::ssize_t(beta.size());
  d["beta_D"] = owned_array(std::move(beta), {n});
  d["growth_rate"] = owned_array(std::move(growth), {n});
  d["frequency"] = owned_array(std::move(frequency), {n});
  if (s.periodic) d["multiplier"] = complex_array(mu), d["period_D_over_U"] = s.T;
  d["stable"] = s.stable;
  d["verdict"] = s.verdict;
  d["accuracy_note"] = kSpanwiseAccuracyNote;
  if (s.beta_D > 0.0) {
    d["most_unstable_beta_D"] = s.beta_D;
    d["most_unstable_wavelength_D"] = s.wavelength_D();
    d["most_unstable_growth_rate"] = s.growth;
  }
  return d;
}

/// The case's parameters for a stability question, its wavenumbers and eigensolver checked (one line each).
NsParams stability_params(const std::string& source, bool is_path, const std::vector<std::string>& overrides,
                          const std::vector<double>& beta_D, const std::string& eigensolver) {
  const Case c = case_of(source, is_path, overrides);
  if (c.model != FlowModel::navier_stokes)
    throw std::invalid_argument("magnus.stability needs model.flow = \"navier-stokes\"");
  check_resolvable(c);
  const NsParams p = ns_params(c);
  if (!(p.U > 0.0)) throw std::invalid_argument("flow.speed must be > 0 (eigenvalues in U/D)");
  for (double b : beta_D)
    if (!(b >= 0.0) || !std::isfinite(b)) throw std::invalid_argument("spanwise: wavenumbers β·D must be finite and ≥ 0");
  if (!known_eigensolver(eigensolver))
    throw std::invalid_argument("eigensolver \"" + eigensolver + "\": expected " + eigensolver_names());
  return p;
}

py::dict stability(const std::string& source, bool is_path, const std::vector<std::string>& overrides,
                   const std::vector<double>& beta_D, const std::string& eigensolver) {
  HopfEvaluation s;
  SpanwiseScan scan;
  NsParams p;
  {
    py::gil_scoped_release nogil;
    p = stability_params(source, is_path, overrides, beta_D, eigensolver);
    s = steady_stability(p, eigensolver);
    if (!beta_D.empty()) scan = spanwise_stability(p, s, beta_D, eigensolver);
  }
  py::dict d;
  d["reynolds"] = p.reynolds();
  d["spin_ratio"] = p.a * p.omega / p.U;
  d["stable"] = s.stability.stable;
  d["eigenvalues"] = complex_array(s.stability.eigenvalues);
  d["covered"] = s.stability.covered;
  if (!beta_D.empty()) d["spanwise"] = scan_dict(scan);
  return d;
}

/// The onset refined on the fine grid fp (spanwise_critical_fine) as onset_3d's "fine_grid".
py::dict fine_dict(const SpanwiseCritical& c, const SpanwiseFine& f, const NsParams& fp) {
  const PolarGrid g = ns_grid(fp);
  py::dict d;
  d["n_theta"] = g.n_theta, d["n_r"] = g.n_r, d["outer_radius_over_a"] = fp.outer_over_a;
  d["found"] = f.found;
  if (!c.found) {
    d["message"] = "the search on the case's grid found no onset";
    return d;
  }
  if (f.found) {
    d["critical_reynolds"] = f.Re_c, d["error_estimate"] = f.bar, d["beta_D"] = f.beta_D;
    d["line_critical_reynolds"] = f.line_Re_c, d["extrapolated"] = f.extrapolated;
  } else {
    d["message"] = f.message;
  }
  std::vector<double> re, growth;
  for (const SpanwiseEvaluation& e : f.evaluations)
    if (!e.scan.points.empty()) re.push_back(e.Re), growth.push_back(e.scan.growth);  // skip a failed scan
  const py::ssize_t n = py::ssize_t(re.size());
  py::dict ev;
  ev["reynolds"] = owned_array(std::move(re), {n});
  ev["growth_rate"] = owned_array(std::move(growth), {n});
  d["evaluations"] = ev;
  d["seconds"] = f.seconds;
  return d;
}

py::dict onset_3d(const std::string& source, bool is_path, const std::vector<std::string>& overrides,
                  const std::vector<double>& beta_D, double Re_a, double Re_b, double tol,
                  const std::string& eigensolver, bool refine, double fine_n, double fine_R) {
  SpanwiseCritical c;
  SpanwiseFine f;
  NsParams p, fp;
  {
    py::gil_scoped_release nogil;
    if (beta_D.empty()) throw std::invalid_argument("spanwise: give the wavenumbers β·D to scan");
    p = stability_params(source, is_path, overrides, beta_D, eigensolver);
    if (refine) {
      const std::string what = fmt::format("fine_grid=({:g}, {:g})", fine_n, fine_R);
      std::vector<std::string> sets = overrides;
      for (const std::string& x : fine_grid_overrides(fine_n, fine_R, p, what)) sets.push_back(x);
      try {
        fp = stability_params(source, is_path, sets, beta_D, eigensolver);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(what + ": " + e.what());
      }
    }
    c = spanwise_critical(p, beta_D, Re_a, Re_b, tol, eigensolver);
    if (refine && c.found) f = spanwise_critical_fine(p, c, fp, eigensolver);
  }
  std::vector<double> re, growth, beta, periodic;
  for (const SpanwiseEvaluation& e : c.evaluations) {
    re.push_back(e.Re), growth.push_back(e.scan.growth), beta.push_back(e.scan.beta_D);
    periodic.push_back(e.scan.periodic ? 1.0 : 0.0);
  }
  py::dict d;
  d["spin_ratio"] = p.a * p.omega / p.U;
  d["found"] = c.found;
  if (c.found) {
    d["critical_reynolds"] = c.Re_c, d["change"] = c.change, d["bracket"] = py::make_tuple(c.lo, c.hi);
    d["beta_D"] = c.beta_D;
    if (c.beta_D > 0.0) d["wavelength_D"] = c.wavelength_D();
  } else {
    d["message"] = c.message;
  }
  const py::ssize_t n = py::ssize_t(re.size());
  py::dict ev;
  ev["reynolds"] = owned_array(std::move(re), {n});
  ev["growth_rate"] = owned_array(std::move(growth), {n});
  ev["beta_D"] = owned_array(std::move(beta), {n});
  ev["periodic"] = owned_array(std::move(periodic), {n});
  d["evaluations"] = ev;
  d["seconds"] = c.seconds;
  d["accuracy_note"] = kSpanwiseAccuracyNote;
  if (refine) d["fine_grid"] = fine_dict(c, f, fp);
  return d;
}

}  // namespace

void bind_stability(py::module_& m) {
  m.def("_stability", &stability,
        "the steady state's leading eigenvalues (U/D) and, with wavenumbers β·D, its 3D stability",
        py::arg("source"), py::arg("is_path"), py::arg("overrides"), py::arg("beta_D"), py::arg("eigensolver"));
  m.def("_onset_3d", &onset_3d, "the Reynolds number in [Re_a, Re_b] where the flow turns three-dimensional",
        py::arg("source"), py::arg("is_path"), py::arg("overrides"), py::arg("beta_D"), py::arg("Re_a"),
        py::arg("Re_b"), py::arg("tolerance"), py::arg("eigensolver"), py::arg("refine") = false,
        py::arg("fine_n") = 0.0, py::arg("fine_R") = 0.0);
}

}  // namespace magnus::python
