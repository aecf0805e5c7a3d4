#include "io/hdf5_io.hpp"

#include <fmt/core.h>
#include <dirent.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/xdmf.hpp"

namespace magnus {

namespace {

/// Closes an HDF5 identifier when it goes out of scope.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
  ~Handle() {
    if (id >= 0) close(id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id; }
};

void quiet_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// HDF5 1.10.8 cannot close a file after a write failed (disk full, file size limit): H5Fclose fails and
// leaves the file open, and the library's atexit clean-up then crashes closing it (SIGSEGV after our error
// message). Every file we open is closed explicitly, so the clean-up is not needed: switch it off before
// anything initialises the library.
const bool hdf5_no_atexit = [] {
  H5dont_atexit();
  return true;
}();

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

/// Fails with what, and the system's reason when the last HDF5 call set errno (": No space left on device").
void check(herr_t status, const std::string& what) {
  if (status >= 0) return;
  const int err = errno;
  fail(err != 0 ? what + ": " + std::strerror(err) : what);
}

/// Links and attributes stay in the object header (checksummed) however many there are: HDF5's "dense"
/// storage for more than 8 puts them in a fractal heap without checksums, and HDF5 1.10 can crash on a
/// damaged one (H5G__dense_iterate frees an uninitialised pointer).
void keep_compact(hid_t ocpl) {
  H5Pset_link_phase_change(ocpl, 1024, 1000);  // groups (and the root group through the file's fcpl)
  H5Pset_attr_phase_change(ocpl, 1024, 1000);
}

}  // namespace

H5Writer::H5Writer(id file) : file_(file) {}

H5Writer::~H5Writer() {
  for (id g : groups_) H5Gclose(g);
}

H5Writer::id H5Writer::group(const std::string& name) {
    Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
    keep_compact(gcpl);
    hid_t g = H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, gcpl, H5P_DEFAULT);
    if (g < 0) fail("cannot create HDF5 group " + name);
    groups_.push_back(g);
    return g;
  }

  void H5Writer::attr(id obj, const char* name, double v) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(a < 0 ? -1 : H5Awrite(a, H5T_NATIVE_DOUBLE, &v), std::string("cannot write attribute ") + name);
  }
  void H5Writer::attr(id obj, const char* name, long v) {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(obj, name, H5T_NATIVE_LONG, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(a < 0 ? -1 : H5Awrite(a, H5T_NATIVE_LONG, &v), std::string("cannot write attribute ") + name);
  }
  void H5Writer::attr(id obj, const char* name, const std::string& v) {
    // Fixed length, not variable: the text is then stored in the attribute itself, inside the checksummed
    // object header (variable-length strings live in the global heap, which has no checksum).
    const std::string text = v.c_str();  // up to the first NUL, as a C string is read back
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type, text.size() + 1);
    H5Tset_strpad(type, H5T_STR_NULLTERM);
    H5Tset_cset(type, H5T_CSET_UTF8);
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle a(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(a < 0 ? -1 : H5Awrite(a, type, text.c_str()), std::string("cannot write attribute ") + name);
  }
  void H5Writer::attr(id obj, const char* name, const char* v) { attr(obj, name, std::string(v)); }
  void H5Writer::attr(id obj, const char* name, const std::optional<double>& v) {
    if (v) attr(obj, name, *v);
  }

  void H5Writer::dataset(id parent, const std::string& name, const std::vector<size_t>& shape,
                         const double* data, const std::string& units, const std::string& description) {
    std::vector<hsize_t> dims(shape.begin(), shape.end());
    Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
    size_t count = 1;
    for (size_t s : shape) count *= s;
    // Every value is checksummed (Fletcher-32, checked by HDF5 on every read), so a damaged file is
    // reported, not read as numbers. The filter needs chunks: whole rows, ~512 KB each (with the filter,
    // writing is then as fast as the plain contiguous layout; much larger chunks are twice as slow).
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (count > 0) {
      std::vector<hsize_t> chunk = dims;
      const hsize_t row = count / dims[0];
      chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], (hsize_t(512) << 10) / (8 * row)));
      check(H5Pset_chunk(dcpl, int(chunk.size()), chunk.data()) < 0 ? -1 : H5Pset_fletcher32(dcpl),
            "cannot set up dataset " + name);
    }
    errno = 0;
    Handle d(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
    if (d < 0) check(-1, "cannot create dataset " + name);
    errno = 0;
    if (count > 0) check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                         "cannot write dataset " + name);
    attr(d, "units", units);
    if (!description.empty()) attr(d, "description", description);
  }


namespace {

void write_file(const FlowResult& r, H5Writer& w) {
  const hid_t file = w.file();
  const Case& c = r.c;
  const PolarGrid& g = r.grid;
  const size_t nr = g.n_r, nt = g.n_theta;
  w.attr(file, "format", "magnus-flow");
  w.attr(file, "format_version", 1L);
  w.attr(file, "software_version", MAGNUS_VERSION);
  w.attr(file, "case", c.source_text);
  w.attr(file, "title", c.title);

  hid_t p = w.group("/parameters");
  w.attr(p, "radius", c.scene.radius);
  w.attr(p, "spin", c.scene.spin);
  if (c.scene.speed > 0.0) w.attr(p, "spin_ratio", c.scene.spin_ratio());
  else w.attr(p, "undefined", "spin_ratio (U = 0)");
  w.attr(p, "speed", c.scene.speed);
  w.attr(p, "density", c.scene.density);
  w.attr(p, "pressure_inf", c.scene.pressure_inf);
  w.attr(p, "circulation", c.scene.Gamma());
  w.attr(p, "circulation_model", c.scene.circulation_given ? "given" : "spin");
  w.attr(p, "outer_radius", g.outer_radius() / g.a);
  w.attr(p, "outer_radius_requested", c.grid.outer_radius);
  w.attr(p, "far_field", to_string(c.grid.far_field));
  w.attr(p, "spacing", to_string(c.grid.spacing));
  w.attr(p, "n_r", long(g.n_r));
  w.attr(p, "n_theta", long(g.n_theta));
  w.attr(p, "method", r.info.method);
  w.attr(p, "stencil", to_string(c.solver.stencil));
  w.attr(p, "units", "radius: m, spin: rad/s, spin_ratio: 1, speed: m/s, density: kg/m^3, "
                     "pressure_inf: Pa, circulation: m^2/s, outer_radius: R/a (1)");

  hid_t gg = w.group("/grid");
  w.dataset(gg, "r", {nr}, g.r.data(), "m");
  w.dataset(gg, "theta", {nt}, g.theta.data(), "rad");
  std::vector<double> x(nr * nt), y(nr * nt);
  for (size_t i = 0; i < nr; ++i)
    for (size_t j = 0; j < nt; ++j) {
      x[i * nt + j] = g.r[i] * std::cos(g.theta[j]);
      y[i * nt + j] = g.r[i] * std::sin(g.theta[j]);
    }
  w.dataset(gg, "x", {nr, nt}, x.data(), "m");
  w.dataset(gg, "y", {nr, nt}, y.data(), "m");

  hid_t f = w.group("/fields");
  for (const auto& name : field_names()) {
    const auto& v = r.fields.get(name);
    if (!v.empty()) w.dataset(f, name, {nr, nt}, v.data(), field_units(name));
  }
  if (c.scene.speed <= 0.0) w.attr(f, "undefined", "cp (U = 0)");

  hid_t s = w.group("/surface");
  w.dataset(s, "theta", {nt}, r.surface.theta.data(), "rad");
  w.dataset(s, "u_theta", {nt}, r.surface.u_theta.data(), "m/s");
  w.dataset(s, "pressure", {nt}, r.surface.pressure.data(), "Pa");
  if (!r.surface.cp.empty()) {
    w.dataset(s, "cp", {nt}, r.surface.cp.data(), "1");
    w.dataset(s, "cp_exact", {nt}, r.surface.cp_exact.data(), "1");
  } else {
    w.attr(s, "undefined", "cp, cp_exact (U = 0)");
  }

  const Forces& fo = r.forces;
  hid_t fg = w.group("/forces");
  w.attr(fg, "lift", fo.lift);
  w.attr(fg, "drag", fo.drag);
  w.attr(fg, "cl", fo.cl);
  w.attr(fg, "cd", fo.cd);
  w.attr(fg, "cl_kutta_joukowski", fo.cl_kutta_joukowski);
  w.attr(fg, "cl_seed_estimate", fo.cl_seed_estimate);
  w.attr(fg, "lift_kutta_joukowski", fo.lift_kutta_joukowski);
  w.attr(fg, "delta_p_top_bottom", fo.delta_p_top_bottom);
  w.attr(fg, "delta_p_top_bottom_exact", fo.delta_p_top_bottom_exact);
  w.attr(fg, "delta_p_seed_estimate", fo.delta_p_seed_estimate);
  w.attr(fg, "circulation_measured", fo.circulation_measured);
  w.attr(fg, "magnus_S", fo.magnus_S);
  w.attr(fg, "magnus_S_exact", fo.magnus_S_exact);
  w.attr(fg, "units", "lift, drag, lift_kutta_joukowski: N/m; cl, cd, cl_*: 1; delta_p_*: Pa; "
                      "circulation_measured: m^2/s; magnus_S*: kg/m");
  if (!fo.cl) w.attr(fg, "undefined", "cl, cd, cl_kutta_joukowski, cl_seed_estimate, magnus_S (U = 0)");
  else if (!fo.magnus_S) w.attr(fg, "undefined", "magnus_S (omega = 0)");

  hid_t st = w.group("/stagnation");
  for (auto [name, pts] : {std::pair{"numeric", &r.stagnation}, std::pair{"exact", &r.stagnation_exact}}) {
    std::vector<double> v;
    for (const auto& q : *pts) v.insert(v.end(), {q.r, q.theta});
    w.dataset(st, name, {pts->size(), 2}, v.data(), "m, rad (columns r, theta)");
  }

  hid_t e = w.group("/errors");
  w.attr(e, "psi_max_rel", r.errors.psi_max_rel);
  w.attr(e, "cp_surface_max_abs", r.errors.cp_surface_max_abs);
  w.attr(e, "cl_rel", r.errors.cl_rel);
  w.attr(e, "circulation_rel", r.errors.circulation_rel);
  if (r.info.estimated_cl_rel >= 0.0) w.attr(e, "cl_rel_estimated", r.info.estimated_cl_rel);
  w.attr(e, "units", "1 (relative), cp_surface_max_abs: 1 (absolute)");

  hid_t t = w.group("/timing");
  w.attr(t, "total_s", r.timing.total_s);
  w.attr(t, "assemble_s", r.timing.assemble_s);
  w.attr(t, "factor_s", r.timing.factor_s);
  w.attr(t, "solve_s", r.timing.solve_s);
  w.attr(t, "postproc_s", r.timing.postproc_s);
  w.attr(t, "units", "s (wall clock)");

  hid_t xg = w.group("/xdmf");
  w.attr(xg, "note", "seam-closed copies (1, n_r, n_theta+1) for ParaView; see the .xmf sidecar");
  for_each_xdmf_array(r, [&](const XdmfArray& a) { w.dataset(xg, a.name, a.shape, a.data.data(), a.units); });
}

}  // namespace

std::string xdmf_path(const std::string& h5_path) {
  const std::string base = base_of(h5_path);
  const auto dot = base.find_last_of('.');
  const std::string stem = dot == std::string::npos || dot == 0 ? h5_path
                           : h5_path.substr(0, h5_path.size() - (base.size() - dot));
  return stem + ".xmf";
}

void write_hdf5_atomic(const std::string& path, const std::function<void(H5Writer&)>& fill,
                       const std::vector<std::pair<std::string, std::string>>& sidecars) {
  quiet_hdf5();
  check_writable(path);
  try {
    AtomicFile h5(path);
    {
      // The 1.10 file format: its metadata (superblock, object headers, chunk indexes) is checksummed.
      Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
      check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST), "cannot set the HDF5 format");
      Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
      keep_compact(fcpl);
      errno = 0;
      Handle file(H5Fcreate(h5.temp().c_str(), H5F_ACC_TRUNC, fcpl, fapl), H5Fclose);
      if (file < 0) check(-1, fmt::format("cannot create '{}'", h5.temp()));
      {
        H5Writer w(file);
        fill(w);
      }
      errno = 0;
      check(H5Fflush(file, H5F_SCOPE_GLOBAL), "cannot flush");
      // Close here, checked: the file is renamed only if every byte made it out.
      errno = 0;
      const hid_t id = file.id;
      file.id = -1;
      check(H5Fclose(id), "cannot close");
    }
    // The sidecars too are complete before any file replaces an earlier one.
    std::vector<std::unique_ptr<AtomicFile>> side;
    for (const auto& [name, text] : sidecars) {
      side.push_back(std::make_unique<AtomicFile>(name));
      write_text(*side.back(), text);
    }
    h5.commit();
    for (auto& f : side) f->commit();
  } catch (const std::exception& e) {
    const std::string what = e.what();
    if (what.rfind("cannot write '", 0) == 0) throw;
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, what));
  }
}

void write_result(const FlowResult& r, const std::string& path) {
  write_hdf5_atomic(path, [&](H5Writer& w) { write_file(r, w); },
                    {{xdmf_path(path), xdmf_text(r, base_of(path))}});
}

// ---------------------------------------------------------------------------------------------
// Reading

ResultFile::ResultFile(const std::string& path) : path_(path) {
  quiet_hdf5();
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) fail(fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  if (S_ISDIR(st.st_mode)) fail(fmt::format("'{}' is a directory, not a result file", path));
  if (!S_ISREG(st.st_mode)) fail(fmt::format("'{}' is not a regular file", path));
  if (::access(path.c_str(), R_OK) != 0) fail(fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  if (st.st_size == 0) fail(fmt::format("'{}' is empty, not a result file", path));
  if (H5Fis_hdf5(path.c_str()) <= 0) fail(fmt::format("'{}' is not an HDF5 file (or it is truncated)", path));
  id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id_ < 0) fail(fmt::format("'{}' is a damaged or truncated HDF5 file: it cannot be opened", path));
  std::string format;
  try {
    if (!has_attr("/", "format")) fail(fmt::format("'{}' is not a magnus result: no 'format' attribute", path));
    format = attr_string("/", "format");
    if (format != "magnus-flow") fail(fmt::format("'{}' is not a magnus result: format is '{}'", path, format));
  } catch (const std::exception&) {
    H5Fclose(id_);
    id_ = -1;
    throw;
  }
}

ResultFile::~ResultFile() {
  if (id_ >= 0) H5Fclose(id_);
}

bool ResultFile::has(const std::string& object) const {
  // Check every path component so that missing parents do not raise errors.
  size_t pos = 0;
  while ((pos = object.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(id_, object.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  return object == "/" || H5Lexists(id_, object.c_str(), H5P_DEFAULT) > 0;
}

bool ResultFile::has_attr(const std::string& object, const std::string& name) const {
  return has(object) && H5Aexists_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

namespace {

/// Opens object@name and checks that it holds exactly one value of type class cls (a foreign or damaged
/// file may hold an array there: reading it into one value would overrun the buffer).
hid_t open_single_attr(hid_t file, const std::string& path, const std::string& object, const std::string& name,
                       std::initializer_list<H5T_class_t> classes, const char* what) {
  const hid_t a = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) fail(fmt::format("'{}': attribute {}@{} cannot be read (damaged file?)", path, object, name));
  Handle space(H5Aget_space(a), H5Sclose);
  Handle type(H5Aget_type(a), H5Tclose);
  const H5T_class_t cls = type < 0 ? H5T_NO_CLASS : H5Tget_class(type);
  if (space < 0 || H5Sget_simple_extent_npoints(space) != 1 ||
      std::find(classes.begin(), classes.end(), cls) == classes.end()) {
    H5Aclose(a);
    fail(fmt::format("'{}': attribute {}@{} is not {}", path, object, name, what));
  }
  return a;
}

}  // namespace

std::vector<double> ResultFile::dataset(const std::string& name, std::vector<size_t>* shape) const {
  if (!has(name)) fail(fmt::format("'{}' has no dataset {}", path_, name));
  Handle d(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (d < 0) fail(fmt::format("'{}': cannot open dataset {}", path_, name));
  Handle type(H5Dget_type(d), H5Tclose);
  const H5T_class_t cls = type < 0 ? H5T_NO_CLASS : H5Tget_class(type);
  if (cls != H5T_FLOAT && cls != H5T_INTEGER) fail(fmt::format("'{}': dataset {} does not hold numbers", path_, name));
  Handle space(H5Dget_space(d), H5Sclose);
  const int rank = space < 0 ? -1 : H5Sget_simple_extent_ndims(space);
  if (rank < 0 || rank > 4) fail(fmt::format("'{}': dataset {} has a bad shape", path_, name));
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space, dims.data(), nullptr) < 0)
    fail(fmt::format("'{}': dataset {} has a bad shape", path_, name));
  // Every value takes storage in the file (ours are not compressed): a shape claiming far more is damage,
  // and must not become a huge allocation.
  hsize_t file_size = 0;
  H5Fget_filesize(id_, &file_size);
  const size_t limit = std::max<size_t>(size_t(file_size), size_t(1) << 20);
  size_t count = 1;
  for (auto v : dims) {
    if (v != 0 && count > limit / v) fail(fmt::format("'{}': dataset {} claims more values than the file holds (damaged file?)", path_, name));
    count *= size_t(v);
  }
  if (shape) shape->assign(dims.begin(), dims.end());
  std::vector<double> out(count);
  if (count > 0 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail(fmt::format("'{}': dataset {} cannot be read: the file is damaged (checksum or structure)", path_, name));
  return out;
}

double ResultFile::attr_double(const std::string& object, const std::string& name) const {
  if (!has_attr(object, name)) fail(fmt::format("'{}': {} has no attribute '{}'", path_, object, name));
  Handle a(open_single_attr(id_, path_, object, name, {H5T_FLOAT, H5T_INTEGER}, "a number"), H5Aclose);
  double v = 0.0;
  if (H5Aread(a, H5T_NATIVE_DOUBLE, &v) < 0)
    fail(fmt::format("'{}': attribute {}@{} is not a number", path_, object, name));
  return v;
}

long ResultFile::attr_int(const std::string& object, const std::string& name) const {
  if (!has_attr(object, name)) fail(fmt::format("'{}': {} has no attribute '{}'", path_, object, name));
  Handle a(open_single_attr(id_, path_, object, name, {H5T_INTEGER}, "an integer"), H5Aclose);
  long v = 0;
  if (H5Aread(a, H5T_NATIVE_LONG, &v) < 0)
    fail(fmt::format("'{}': attribute {}@{} is not an integer", path_, object, name));
  return v;
}

std::string ResultFile::attr_string(const std::string& object, const std::string& name) const {
  if (!has_attr(object, name)) fail(fmt::format("'{}': {} has no attribute '{}'", path_, object, name));
  Handle a(open_single_attr(id_, path_, object, name, {H5T_STRING}, "a string"), H5Aclose);
  Handle type(H5Aget_type(a), H5Tclose);
  if (H5Tis_variable_str(type) > 0) {
    Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
    char* p = nullptr;
    if (H5Tset_size(mem, H5T_VARIABLE) < 0 || H5Tset_cset(mem, H5Tget_cset(type)) < 0 || H5Aread(a, mem, &p) < 0)
      fail(fmt::format("'{}': cannot read {}@{}", path_, object, name));
    if (!p) return "";
    std::string s(p);
    H5free_memory(p);
    return s;
  }
  const size_t n = H5Tget_size(type);
  if (n == 0 || n > (size_t(64) << 20)) fail(fmt::format("'{}': attribute {}@{} has a bad size", path_, object, name));
  std::string s(n, '\0');
  if (H5Aread(a, type, s.data()) < 0) fail(fmt::format("'{}': cannot read {}@{}", path_, object, name));
  s.resize(std::strlen(s.c_str()));
  return s;
}

std::vector<std::pair<std::string, std::vector<size_t>>> ResultFile::datasets() const {
  std::vector<std::pair<std::string, std::vector<size_t>>> out;
  auto visit = [](hid_t obj, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type != H5O_TYPE_DATASET) return 0;
    auto* o = static_cast<std::vector<std::pair<std::string, std::vector<size_t>>>*>(data);
    Handle d(H5Dopen2(obj, name, H5P_DEFAULT), H5Dclose);
    Handle space(H5Dget_space(d), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(size_t(std::max(rank, 0)));
    if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    o->push_back({std::string("/") + name, std::vector<size_t>(dims.begin(), dims.end())});
    return 0;
  };
  if (H5Ovisit(id_, H5_INDEX_NAME, H5_ITER_INC, visit, &out) < 0)
    fail(fmt::format("'{}' is damaged: its objects cannot be listed", path_));
  return out;
}

}  // namespace magnus
