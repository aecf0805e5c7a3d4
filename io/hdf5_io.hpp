#pragma once
// The magnus-flow HDF5 result: written atomically, read back for inspect/compare/tests.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "base/atomic_file.hpp"
#include "postproc/result.hpp"

namespace magnus {

/// Groups, scalar attributes (strings fixed-length UTF-8, inside the checksummed object headers) and
/// datasets (chunked, Fletcher-32 checksummed, with a units attribute) of an HDF5 file being written.
class H5Writer {
 public:
  using id = std::int64_t;  ///< an HDF5 identifier (hid_t)
  explicit H5Writer(id file);
  ~H5Writer();
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;
  id file() const { return file_; }
  id group(const std::string& name);
  void attr(id obj, const char* name, double v);
  void attr(id obj, const char* name, long v);
  void attr(id obj, const char* name, const std::string& v);
  void attr(id obj, const char* name, const char* v);
  void attr(id obj, const char* name, const std::optional<double>& v);  ///< nothing when empty
  void dataset(id parent, const std::string& name, const std::vector<size_t>& shape, const double* data,
               const std::string& units, const std::string& description = "");
  /// An integer dataset (32-bit), always compressed (gzip 6 + shuffle): connectivity and the like.
  void int_dataset(id parent, const std::string& name, const std::vector<size_t>& shape, const int* data,
                   const std::string& units, const std::string& description = "");
  /// One column of a virtual dataset: the whole of source (same file) in row-major order, into column
  /// `column` of the view (or the whole view when the view has rank 1).
  struct ViewSource {
    std::string source;  ///< "/fields/u_x"
    size_t column = 0;
    long block = -1;  ///< ≥ 0: only block `block` along the source's first axis (one stored state)
  };
  /// A virtual dataset (no storage of its own): a (n) or (n, k) view whose columns are whole stored
  /// datasets of n values (or one block of n values of a larger one); columns without a source read as 0.
  void view(id parent, const std::string& name, const std::vector<size_t>& shape,
            const std::vector<ViewSource>& sources, const std::string& units,
            const std::string& description = "");
  /// A dataset's one-line description, twice: `description` (magnus's own name) and `long_name` (the CF
  /// conventions' name, which xarray and netCDF tools show); nothing when empty.
  void described(id obj, const std::string& description);
  /// A numeric attribute with its unit in the companion attribute NAME_units (format version 2).
  void attr_with_units(id obj, const char* name, double v, const std::string& units);
  /// An already written object (dataset or group) by path, to add attributes; closed with the writer.
  id open(const std::string& path);
  /// Make the 1-D dataset at scale_path an HDF5 dimension scale named name (H5DSset_scale).
  void make_scale(const std::string& scale_path, const std::string& name);
  /// Attach the dimension scale at scale_path to dimension dim of the dataset at path (H5DSattach_scale).
  void attach_scale(const std::string& path, const std::string& scale_path, unsigned dim);
  /// A second name (hard link) for the object at path: one object, no copy (H5Lcreate_hard).
  void link(const std::string& path, const std::string& new_path);
  /// gzip level (0–9) of the double datasets written from now on, with the shuffle filter; 0: none.
  void set_compression(int level);
  int compression() const { return compression_; }

 private:
  id file_;
  int compression_ = 0;
  std::vector<id> groups_, objects_;
};

/// Create the HDF5 file at path atomically: fill writes it under a temporary name beside it (1.10 format,
/// checksummed metadata), each sidecar (path, text) is written likewise, and all are renamed into place
/// only once all are complete. Throws one line naming path; leaves no temporary behind.
/// compression: gzip level 0–9 of the double datasets (0: none; the case key output.compression).
void write_hdf5_atomic(const std::string& path, const std::function<void(H5Writer&)>& fill,
                       const std::vector<std::pair<std::string, std::string>>& sidecars = {},
                       int compression = 0);

/// Write r to path (temporary name beside it, then rename) with its .xmf sidecar, format version 2
/// (io/schema.hpp); compression: gzip level 0–9 of the stored datasets (0: none).
/// Throws std::runtime_error with one line naming the file; leaves no partial file behind.
void write_result(const FlowResult& r, const std::string& path, int compression = 0);

/// The .xmf sidecar name for a result path (extension replaced by .xmf).
std::string xdmf_path(const std::string& h5_path);

/// A read-only magnus-flow file. Throws std::runtime_error with one line on anything malformed.
class ResultFile {
 public:
  explicit ResultFile(const std::string& path);
  /// Open a file whose root `format` is one of formats (e.g. {"magnus-flow", "magnus-sweep"}).
  ResultFile(const std::string& path, const std::vector<std::string>& formats);
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  bool has(const std::string& object) const;
  bool has_attr(const std::string& object, const std::string& name) const;
  /// A dataset's values (row-major) and its shape.
  std::vector<double> dataset(const std::string& name, std::vector<size_t>* shape = nullptr) const;
  double attr_double(const std::string& object, const std::string& name) const;
  long attr_int(const std::string& object, const std::string& name) const;
  std::string attr_string(const std::string& object, const std::string& name) const;
  /// Every dataset below / with its shape.
  std::vector<std::pair<std::string, std::vector<size_t>>> datasets() const;
  /// Names of the attributes of object, in creation order (name order for files without it).
  std::vector<std::string> attributes(const std::string& object) const;
  /// Whether the attribute holds text.
  bool attr_is_text(const std::string& object, const std::string& name) const;
  /// The root `format` attribute ("magnus-flow", "magnus-sweep").
  const std::string& format() const { return format_; }
  /// The root `format_version` (1 when absent or unreadable as an integer).
  long version() const;
  const std::string& path() const { return path_; }

 private:
  std::string path_, format_;
  long id_ = -1;
};

}  // namespace magnus
