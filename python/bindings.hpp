#pragma once
// The Python module's C++ side (module _magnus, wrapped by python/magnus/__init__.py): conversion only.
// Results are shared between C++ and numpy: an array of a result views the result's own vector and keeps
// the result alive through its capsule (no copy); computed arrays own their vector the same way.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "postproc/result.hpp"

namespace magnus::python {

namespace py = pybind11;

/// A result held by Python: one FlowResult shared by every array handed out from it.
struct PyResult {
  std::shared_ptr<const FlowResult> r;
};

/// A read-only numpy array of `shape` over v's storage, keeping `owner` alive (no copy).
py::array view_of(const std::shared_ptr<const FlowResult>& owner, const std::vector<double>& v,
                  std::vector<py::ssize_t> shape);

/// A read-only numpy array that owns v (moved, not copied).
py::array owned_array(std::vector<double> v, std::vector<py::ssize_t> shape);

/// The class _magnus.Result: forces, parameters, fields, grid, surface, history, units, write().
void bind_result(py::module_& m);

/// _magnus._sweep: the potential flow's spin-ratio (or circulation) sweep as columns.
void bind_sweep(py::module_& m);

/// _magnus._stability: a navier-stokes steady state's eigenvalues and its spanwise (3D) stability.
void bind_stability(py::module_& m);

/// The case of a run or sweep: from a file (is_path) or from TOML text (origin "<dict>"), with overrides
/// "section.key=value". Throws CaseError with the command line's one-line message.
Case case_of(const std::string& source, bool is_path, const std::vector<std::string>& overrides);

}  // namespace magnus::python
