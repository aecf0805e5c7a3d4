#include "io/hdf5_io.hpp"

#include <dirent.h>
#include <fmt/core.h>
#include <hdf5.h>
#include <hdf5_hl.h>
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

#include "base/atomic_file.hpp"
#include "io/h5_util.hpp"

namespace magnus {

using h5::check;
using h5::fail;
using h5::Handle;
using h5::keep_compact;

namespace {

// HDF5 1.10.8 cannot close a file after a write failed (disk full, file size limit): H5Fclose fails and
// leaves the file open, and the library's atexit clean-up then crashes closing it (SIGSEGV after our error
// message). Every file we open is closed explicitly, so the clean-up is not needed: switch it off before
// anything initialises the library.
const bool hdf5_no_atexit = [] {
  H5dont_atexit();
  return true;
}();

}  // namespace

H5Writer::H5Writer(id file) : file_(file) {}

H5Writer::~H5Writer() {
  for (id o : objects_) H5Oclose(o);
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

H5Writer::id H5Writer::open(const std::string& path) {
  const hid_t o = H5Oopen(file_, path.c_str(), H5P_DEFAULT);
  if (o < 0) fail("cannot open HDF5 object " + path);
  objects_.push_back(o);
  return o;
}

void H5Writer::set_compression(int level) {
  if (level < 0 || level > 9) fail(fmt::format("compression level {} is not in 0–9", level));
  compression_ = level;
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
void H5Writer::described(id obj, const std::string& description) {
  if (description.empty()) return;
  attr(obj, "description", description);
  attr(obj, "long_name", description);
}
void H5Writer::attr_with_units(id obj, const char* name, double v, const std::string& units) {
  attr(obj, name, v);
  attr(obj, (std::string(name) + "_units").c_str(), units);
}

namespace {

/// Chunked layout (whole rows, ~512 KB a chunk) with the filters: shuffle + gzip at level (if > 0),
/// then Fletcher-32 (checked by HDF5 on every read, so a damaged file is reported, not read as numbers).
void chunked(hid_t dcpl, const std::vector<hsize_t>& dims, size_t value_size, int level,
             const std::string& name) {
  size_t count = 1;
  for (auto d : dims) count *= size_t(d);
  if (count == 0) return;
  std::vector<hsize_t> chunk = dims;
  const hsize_t row = count / dims[0];
  chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], (hsize_t(512) << 10) / (value_size * row)));
  herr_t s = H5Pset_chunk(dcpl, int(chunk.size()), chunk.data());
  if (s >= 0 && level > 0) s = H5Pset_shuffle(dcpl) < 0 ? -1 : H5Pset_deflate(dcpl, unsigned(level));
  if (s >= 0) s = H5Pset_fletcher32(dcpl);
  check(s, "cannot set up dataset " + name);
}

}  // namespace

namespace {

/// One chunked, checksummed dataset of count values of the memory type mem stored as file, with its units
/// and description (the shared body of the double and int datasets).
void write_dataset(H5Writer& w, H5Writer::id parent, const std::string& name,
                   const std::vector<size_t>& shape, hid_t mem, hid_t file, size_t value_size, int level,
                   const void* data, const std::string& units, const std::string& description) {
  std::vector<hsize_t> dims(shape.begin(), shape.end());
  Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
  size_t count = 1;
  for (size_t n : shape) count *= n;
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  chunked(dcpl, dims, value_size, level, name);
  errno = 0;
  Handle d(H5Dcreate2(parent, name.c_str(), file, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
  if (d < 0) check(-1, "cannot create dataset " + name);
  errno = 0;
  if (count > 0) check(H5Dwrite(d, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "cannot write dataset " + name);
  w.attr(d, "units", units);
  w.described(d, description);
}

}  // namespace

void H5Writer::dataset(id parent, const std::string& name, const std::vector<size_t>& shape,
                       const double* data, const std::string& units, const std::string& description) {
  write_dataset(*this, parent, name, shape, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, sizeof(double),
                compression_, data, units, description);
}

void H5Writer::int_dataset(id parent, const std::string& name, const std::vector<size_t>& shape,
                           const int* data, const std::string& units, const std::string& description) {
  // Connectivity compresses well and is read whole: always gzip level 6.
  write_dataset(*this, parent, name, shape, H5T_NATIVE_INT, H5T_STD_I32LE, sizeof(int), 6, data, units,
                description);
}

void H5Writer::view(id parent, const std::string& name, const std::vector<size_t>& shape,
                    const std::vector<ViewSource>& sources, const std::string& units,
                    const std::string& description) {
  std::vector<hsize_t> dims(shape.begin(), shape.end());
  Handle vspace(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const double zero = 0.0;
  herr_t s = H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &zero);
  for (const auto& src : sources) {
    Handle d(H5Dopen2(file_, src.source.c_str(), H5P_DEFAULT), H5Dclose);
    Handle sspace(d < 0 ? -1 : H5Dget_space(d), H5Sclose);
    if (sspace < 0) fail("cannot open " + src.source + " for the view " + name);
    if (src.block >= 0 && s >= 0) {
      // Block `block` along the first axis: [block, 0, …] + [1, whole, …].
      const int rank = H5Sget_simple_extent_ndims(sspace);
      std::vector<hsize_t> sdims(size_t(std::max(rank, 1)), 0);
      if (rank < 1 || H5Sget_simple_extent_dims(sspace, sdims.data(), nullptr) < 0 ||
          hsize_t(src.block) >= sdims[0])
        fail(fmt::format("the view {} asks for block {} of {}, which has none", name, src.block, src.source));
      std::vector<hsize_t> sstart(sdims.size(), 0), scount = sdims;
      sstart[0] = hsize_t(src.block);
      scount[0] = 1;
      s = H5Sselect_hyperslab(sspace, H5S_SELECT_SET, sstart.data(), nullptr, scount.data(), nullptr);
    }
    std::vector<hsize_t> start(dims.size(), 0), count = dims;
    if (dims.size() == 2) start[1] = src.column, count[1] = 1;
    if (s >= 0) s = H5Sselect_hyperslab(vspace, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
    // Same number of values in both selections; the shapes may differ (row-major order maps them).
    if (s >= 0) s = H5Pset_virtual(dcpl, vspace, ".", src.source.c_str(), sspace);
  }
  check(s, "cannot set up the view " + name);
  H5Sselect_all(vspace);
  Handle d(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_DOUBLE, vspace, H5P_DEFAULT, dcpl, H5P_DEFAULT),
           H5Dclose);
  if (d < 0) check(-1, "cannot create the view " + name);
  attr(d, "units", units);
  described(d, description);
}

void H5Writer::make_scale(const std::string& scale_path, const std::string& name) {
  check(H5DSset_scale(open(scale_path), name.c_str()), "cannot make " + scale_path + " a dimension scale");
}

void H5Writer::link(const std::string& path, const std::string& new_path) {
  check(H5Lcreate_hard(file_, path.c_str(), file_, new_path.c_str(), H5P_DEFAULT, H5P_DEFAULT),
        "cannot name " + path + " also " + new_path);
}

void H5Writer::attach_scale(const std::string& path, const std::string& scale_path, unsigned dim) {
  Handle d(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle sc(H5Dopen2(file_, scale_path.c_str(), H5P_DEFAULT), H5Dclose);
  check(d < 0 || sc < 0 ? -1 : H5DSattach_scale(d, sc, dim), "cannot attach " + scale_path + " to " + path);
}

std::string xdmf_path(const std::string& h5_path) {
  const std::string base = base_of(h5_path);
  const auto dot = base.find_last_of('.');
  const std::string stem = dot == std::string::npos || dot == 0
                               ? h5_path
                               : h5_path.substr(0, h5_path.size() - (base.size() - dot));
  return stem + ".xmf";
}

void write_hdf5_atomic(const std::string& path, const std::function<void(H5Writer&)>& fill,
                       const std::vector<std::pair<std::string, std::string>>& sidecars, int compression) {
  h5::quiet();
  if (compression < 0 || compression > 9)
    throw std::invalid_argument(fmt::format("compression level {} is not in 0–9", compression));
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
        w.set_compression(compression);
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

}  // namespace magnus
