// The module _magnus: run, read, and the exception translation. Every solve and file access runs with the
// GIL released; errors carry exactly the command line's one-line message (what `magnus` prints after
// "magnus: error: "): ValueError for bad input (case keys, values, arguments), RuntimeError otherwise.
#include <Python.h>
#include <pybind11/stl.h>

#include <atomic>
#include <stdexcept>

#include "base/atomic_file.hpp"
#include "io/case_file.hpp"
#include "io/hdf5_io.hpp"
#include "base/output_owner.hpp"
#include "io/result_reader.hpp"
#include "io/stability_file.hpp"
#include "postproc/run_case.hpp"
#include "bindings.hpp"

namespace magnus::python {

py::array view_of(const std::shared_ptr<const FlowResult>& owner, const std::vector<double>& v,
                  std::vector<py::ssize_t> shape) {
  auto* keep = new std::shared_ptr<const FlowResult>(owner);
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<const FlowResult>*>(p); });
  py::array a(py::dtype::of<double>(), std::move(shape), {}, v.data(), base);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::array owned_array(std::vector<double> v, std::vector<py::ssize_t> shape) {
  auto* keep = new std::vector<double>(std::move(v));
  py::capsule base(keep, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  py::array a(py::dtype::of<double>(), std::move(shape), {}, keep->data(), base);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

Case case_of(const std::string& source, bool is_path, const std::vector<std::string>& overrides) {
  return is_path ? load_case(source, overrides) : parse_case(source, "<dict>", overrides);
}

namespace {

/// Python's Ctrl-C during a navier-stokes run: checked between time steps (with the GIL, every few steps).
struct Interrupt {
  std::atomic<bool> raised{false};
  long steps = 0;
  bool keep_going() {
    if (++steps % 16 != 0) return true;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) raised = true;
    return !raised;
  }
};

/// magnus.run: solve the case (no file unless output is given: then written atomically, as `magnus run -o`).
PyResult run(const std::string& source, bool is_path, const std::vector<std::string>& overrides, int threads,
             const std::string& output, bool force, const std::vector<std::string>& onset3d) {
  Interrupt interrupt;
  // force: replace an existing output magnus did not write (as --force), for this call only.
  struct Force {
    explicit Force(bool on) { set_replace_any_file(on); }
    ~Force() { set_replace_any_file(false); }
  } const forced(force);
  std::shared_ptr<FlowResult> r;
  {
    py::gil_scoped_release nogil;
    Case c = case_of(source, is_path, overrides);
    if (!output.empty()) {
      c.output.file = output;
      c.source_text = to_toml(c);
      if (is_path) check_distinct_paths({source}, {output, xdmf_path(output)});
      check_writable(output);
      check_writable(xdmf_path(output));
    }
    RunHooks hooks;
    give_onset3d(hooks, c, onset3d, "onset3d");
    hooks.threads = threads;
    hooks.viscous.on_step = [&interrupt](const NsState&, const ViscousForces&) {
      return interrupt.keep_going();
    };
    r = std::make_shared<FlowResult>(run_case(c, hooks));
    if (interrupt.raised) {
      py::gil_scoped_acquire gil;
      throw py::error_already_set();
    }
    if (!output.empty()) write_result(*r, output, c.output.compression);
  }
  return PyResult{std::move(r)};
}

PyResult read_path(const std::string& path) {
  py::gil_scoped_release nogil;
  return PyResult{std::make_shared<FlowResult>(read_result(path))};
}

}  // namespace

}  // namespace magnus::python

PYBIND11_MODULE(_magnus, m) {
  using namespace magnus::python;
  m.doc() = "magnus: flow past a spinning cylinder (C++ core; use the package magnus)";
  m.attr("__version__") = MAGNUS_VERSION;
  // Bad input (a case key, a value, an argument) is a ValueError; anything else a RuntimeError. The
  // message is the command line's line without its "magnus: error: " prefix.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const magnus::CaseError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::out_of_range& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::domain_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bind_result(m);
  bind_sweep(m);
  bind_stability(m);
  m.def("_run", &run, "solve a case (path or TOML text) with overrides; write `output` if not empty",
        py::arg("source"), py::arg("is_path"), py::arg("overrides"), py::arg("threads"), py::arg("output"),
        py::arg("force") = false, py::arg("onset3d") = std::vector<std::string>{});
  m.def("_read", &read_path, "read a magnus-flow result file", py::arg("path"));
}
