#include "plot/sweep_reader.hpp"

#include <hdf5.h>

#include <fmt/core.h>
#include <stdexcept>

namespace magnus {
namespace {

std::string read_string_attr(hid_t obj, const char* name) {
  if (H5Aexists(obj, name) <= 0) return {};
  const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0) return {};
  const hid_t type = H5Aget_type(a);
  std::string out;
  if (H5Tget_class(type) == H5T_STRING) {
    const hid_t mem = H5Tcopy(H5T_C_S1);
    H5Tset_cset(mem, H5Tget_cset(type));  // UTF-8 to ASCII has no conversion path
    if (H5Tis_variable_str(type) > 0) {
      char* p = nullptr;
      H5Tset_size(mem, H5T_VARIABLE);
      if (H5Aread(a, mem, &p) >= 0 && p) {
        out = p;
        H5free_memory(p);
      }
    } else {
      const size_t n = H5Tget_size(type);
      std::string buf(n + 1, '\0');
      H5Tset_size(mem, n + 1);
      if (H5Aread(a, mem, buf.data()) >= 0) out = buf.c_str();
    }
    H5Tclose(mem);
  }
  H5Tclose(type);
  H5Aclose(a);
  return out;
}

herr_t numeric_attr(hid_t obj, const char* name, const H5A_info_t*, void* data) {
  auto* params = static_cast<std::map<std::string, double>*>(data);
  const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0) return 0;
  const hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  const H5T_class_t cls = H5Tget_class(type);
  double v = 0.0;
  if ((cls == H5T_FLOAT || cls == H5T_INTEGER) && H5Sget_simple_extent_npoints(space) == 1 &&
      H5Aread(a, H5T_NATIVE_DOUBLE, &v) >= 0)
    (*params)[name] = v;
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(a);
  return 0;
}

}  // namespace

SweepFileData read_sweep_columns(const std::string& path, const std::vector<std::string>& columns) {
  H5E_auto2_t old_func = nullptr;
  void* old_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &old_func, &old_data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become one line, not an HDF5 trace
  struct Restore {
    H5E_auto2_t f;
    void* d;
    ~Restore() { H5Eset_auto2(H5E_DEFAULT, f, d); }
  } restore{old_func, old_data};
  if (H5Fis_hdf5(path.c_str()) <= 0) throw std::runtime_error(fmt::format("'{}' is not an HDF5 file", path));
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error(fmt::format("'{}' cannot be opened", path));
  SweepFileData d;
  const hid_t root = H5Gopen2(file, "/", H5P_DEFAULT);
  if (root >= 0) {
    d.format = read_string_attr(root, "format");
    d.title = read_string_attr(root, "title");
    d.variable = read_string_attr(root, "variable");
    H5Gclose(root);
  }
  if (H5Lexists(file, "/parameters", H5P_DEFAULT) > 0) {
    const hid_t g = H5Oopen(file, "/parameters", H5P_DEFAULT);
    if (g >= 0) {
      hsize_t idx = 0;
      H5Aiterate2(g, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, numeric_attr, &d.parameters);
      H5Oclose(g);
    }
  }
  const bool have_sweep = H5Lexists(file, "/sweep", H5P_DEFAULT) > 0;
  for (const auto& name : columns) {
    const std::string obj = "/sweep/" + name;
    if (!have_sweep || H5Lexists(file, obj.c_str(), H5P_DEFAULT) <= 0) continue;
    const hid_t ds = H5Dopen2(file, obj.c_str(), H5P_DEFAULT);
    if (ds < 0) continue;
    const hid_t space = H5Dget_space(ds);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::vector<double> v(n > 0 ? size_t(n) : 0);
    const bool ok = n > 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0;
    H5Sclose(space);
    H5Dclose(ds);
    if (!ok) {
      H5Fclose(file);
      throw std::runtime_error(fmt::format("'{}': {} cannot be read", path, obj));
    }
    d.columns[name] = std::move(v);
  }
  H5Fclose(file);
  return d;
}

}  // namespace magnus
