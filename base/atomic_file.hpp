#pragma once
// Every output magnus writes goes through here: it appears only when complete (a temporary file beside
// the target, renamed onto it), an existing file is replaced only then, a symlink is followed (its target
// is replaced, the link stays), and nothing that is not a regular file (a directory, a FIFO, a device, a
// socket) is ever replaced. "-" means standard output for text outputs.
#include <string>
#include <vector>

namespace magnus {

/// True for the names of standard output: "-", /dev/stdout, /dev/fd/1, /proc/self/fd/1.
bool is_stdout(const std::string& path);

/// The file an output path names: symlinks followed to the final target (a dangling link gives the
/// path it points to). Throws one line naming the path if it is a directory, a FIFO, a device or a socket.
std::string output_target(const std::string& path);

/// Before solving: the output's directory exists and is writable and the target (if any) is a regular
/// writable file. "" and "-" pass. Throws one line naming the path.
void check_writable(const std::string& path);

/// check_writable for a binary output (HDF5, PNG): "-" is refused too, in one line naming `what`.
void check_file_writable(const std::string& path, const char* what);

/// Refuse an output that names an input or another output (after following links): one line naming both.
/// "" and "-" are skipped.
void check_distinct_paths(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

/// A file being written under a temporary name beside its target (".NAME.tmp-PID", created exclusively and
/// locked until committed), renamed onto the target by commit(); removed on destruction if never
/// committed. Temporaries that killed writers of the same target left behind (no lock held) are removed
/// first.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// The path as given (for messages).
  const std::string& path() const { return path_; }
  /// The temporary file to write (it exists, empty, when the constructor returns).
  const std::string& temp() const { return temp_; }
  /// Rename the temporary onto the target. Throws one line naming the path.
  void commit();

 private:
  std::string path_, target_, temp_;
  bool committed_ = false;
  int lock_fd_ = -1;  ///< holds the temporary's lock (try_lock_file)
};

/// Write text to the temporary file of f (the file is then complete but not yet committed). Throws one line.
void write_text(AtomicFile& f, const std::string& text);

/// A text output (CSV, JSON, tables): "-" writes to standard output, anything else atomically.
void write_text_output(const std::string& path, const std::string& text);

/// The directory part of a path ("." when it has none) and the name part.
std::string dir_of(const std::string& path);
std::string base_of(const std::string& path);

}  // namespace magnus
