#include <fmt/core.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "base/output_owner.hpp"
#include "io/h5_util.hpp"
#include "io/hdf5_io.hpp"

namespace magnus {

using h5::fail;
using h5::Handle;

namespace {

/// A magnus HDF5 output (result, sweep, checkpoint, stability): what base/output_owner lets magnus replace.
bool hdf5_by_magnus(const std::string& target) {
  try {
    const ResultFile f(target, {"magnus-flow", "magnus-sweep", "magnus-checkpoint", "magnus-stability"});
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

/// Installed before main: any program that links the HDF5 reader recognises magnus's HDF5 outputs.
const bool hdf5_owner_check_installed = (set_hdf5_owner_check(&hdf5_by_magnus), true);

}  // namespace

ResultFile::ResultFile(const std::string& path) : ResultFile(path, std::vector<std::string>{"magnus-flow"}) {}

ResultFile::ResultFile(const std::string& path, const std::vector<std::string>& formats) : path_(path) {
  h5::quiet();
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) fail(fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  if (S_ISDIR(st.st_mode)) fail(fmt::format("'{}' is a directory, not a result file", path));
  if (!S_ISREG(st.st_mode)) fail(fmt::format("'{}' is not a regular file", path));
  if (::access(path.c_str(), R_OK) != 0)
    fail(fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  if (st.st_size == 0) fail(fmt::format("'{}' is empty, not a result file", path));
  if (H5Fis_hdf5(path.c_str()) <= 0) fail(fmt::format("'{}' is not an HDF5 file (or it is truncated)", path));
  id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id_ < 0) fail(fmt::format("'{}' is a damaged or truncated HDF5 file: it cannot be opened", path));
  std::string format;
  try {
    if (!has_attr("/", "format"))
      fail(fmt::format("'{}' is not a magnus result: no 'format' attribute", path));
    format = attr_string("/", "format");
    if (std::find(formats.begin(), formats.end(), format) == formats.end())
      fail(format.rfind("magnus-", 0) == 0
               ? fmt::format("'{}' is a {} file, not {}", path, format,
                             formats.size() == 1 ? "a " + formats.front() + " file" : "of the kind this reads")
               : fmt::format("'{}' is not a magnus result: format is '{}'", path, format));
    format_ = format;
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
hid_t open_single_attr(hid_t file, const std::string& path, const std::string& object,
                       const std::string& name, std::initializer_list<H5T_class_t> classes,
                       const char* what) {
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
  if (cls != H5T_FLOAT && cls != H5T_INTEGER)
    fail(fmt::format("'{}': dataset {} does not hold numbers", path_, name));
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
    if (v != 0 && count > limit / v)
      fail(fmt::format("'{}': dataset {} claims more values than the file holds (damaged file?)", path_,
                       name));
    count *= size_t(v);
  }
  if (shape) shape->assign(dims.begin(), dims.end());
  std::vector<double> out(count);
  if (count > 0 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail(fmt::format("'{}': dataset {} cannot be read: the file is damaged (checksum or structure)", path_,
                     name));
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
    if (H5Tset_size(mem, H5T_VARIABLE) < 0 || H5Tset_cset(mem, H5Tget_cset(type)) < 0 ||
        H5Aread(a, mem, &p) < 0)
      fail(fmt::format("'{}': cannot read {}@{}", path_, object, name));
    if (!p) return "";
    std::string s(p);
    H5free_memory(p);
    return s;
  }
  const size_t n = H5Tget_size(type);
  if (n == 0 || n > (size_t(64) << 20))
    fail(fmt::format("'{}': attribute {}@{} has a bad size", path_, object, name));
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

std::vector<std::string> ResultFile::attributes(const std::string& object) const {
  std::vector<std::string> out;
  if (!has(object)) return out;
  auto visit = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  Handle o(H5Oopen(id_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (o < 0) fail(fmt::format("'{}': {} cannot be opened (damaged file?)", path_, object));
  hsize_t n = 0;
  if (H5Aiterate2(o, H5_INDEX_CRT_ORDER, H5_ITER_INC, &n, visit, &out) < 0) {
    out.clear();
    n = 0;
    if (H5Aiterate2(o, H5_INDEX_NAME, H5_ITER_INC, &n, visit, &out) < 0)
      fail(fmt::format("'{}': the attributes of {} cannot be listed (damaged file?)", path_, object));
  }
  return out;
}

bool ResultFile::attr_is_text(const std::string& object, const std::string& name) const {
  if (!has_attr(object, name)) return false;
  Handle a(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  Handle type(a < 0 ? -1 : H5Aget_type(a), H5Tclose);
  return type >= 0 && H5Tget_class(type) == H5T_STRING;
}

long ResultFile::version() const {
  if (!has_attr("/", "format_version")) return 1;
  try {
    return attr_int("/", "format_version");
  } catch (const std::exception&) {
    return 1;
  }
}

}  // namespace magnus
