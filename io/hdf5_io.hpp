#pragma once
// The magnus-flow HDF5 result (DESIGN §5): written atomically, read back for inspect/compare/tests.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>
#include "io/atomic_file.hpp"
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

 private:
  id file_;
  std::vector<id> groups_;
};

/// Create the HDF5 file at path atomically: fill writes it under a temporary name beside it (1.10 format,
/// checksummed metadata), each sidecar (path, text) is written likewise, and all are renamed into place
/// only once all are complete. Throws one line naming path; leaves no temporary behind.
void write_hdf5_atomic(const std::string& path, const std::function<void(H5Writer&)>& fill,
                       const std::vector<std::pair<std::string, std::string>>& sidecars = {});

/// Write r to path (temporary name beside it, then rename) with its .xmf sidecar.
/// Throws std::runtime_error with one line naming the file; leaves no partial file behind.
void write_result(const FlowResult& r, const std::string& path);

/// The .xmf sidecar name for a result path (extension replaced by .xmf).
std::string xdmf_path(const std::string& h5_path);

/// A read-only magnus-flow file. Throws std::runtime_error with one line on anything malformed.
class ResultFile {
 public:
  explicit ResultFile(const std::string& path);
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
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  long id_ = -1;
};

}  // namespace magnus
