#pragma once
// The magnus-flow HDF5 result (DESIGN §5): written atomically, read back for inspect/compare/tests.
#include <map>
#include <memory>
#include <string>
#include <vector>
#include "postproc/result.hpp"

namespace magnus {

/// Write r to path (temporary name beside it, then rename) with its .xmf sidecar.
/// Throws std::runtime_error with one line naming the file; leaves no partial file behind.
void write_result(const FlowResult& r, const std::string& path);

/// The .xmf sidecar name for a result path (extension replaced by .xmf).
std::string xdmf_path(const std::string& h5_path);

/// Check that path can be written (its directory exists and is writable); throws one line if not.
void check_writable(const std::string& path);

/// Refuse an output path that names an input or another output (one line naming both); "" is skipped.
void check_distinct_paths(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

/// Write text to path atomically (temporary name beside it, then rename).
void write_text_atomic(const std::string& path, const std::string& text);

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
