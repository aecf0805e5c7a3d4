#pragma once
// Locks that the kernel releases when their process ends, however it ends (SIGKILL included): a killed
// writer never blocks the next one. Open-file-description locks (fcntl F_OFD_SETLK) on Linux: held per
// open file, unaffected by other descriptors of the same file closing, and independent of HDF5's own
// flock on the files it opens.
#include <string>

namespace magnus {

/// Take an exclusive lock on the whole of the open file fd without waiting: true if taken, false if
/// another open file holds one.
bool try_lock_file(int fd);

/// A lock on the output of a `magnus run` for the length of the run: the file PATH.lock beside the
/// output's target (symlinks followed), holding the PID of the run that holds it. A second run to the same
/// output is refused in one line naming the first. The file is removed when the lock is released; one that
/// a killed run left is taken over.
class OutputLock {
 public:
  /// Throws std::runtime_error, one line: "cannot write 'PATH': another magnus run (PID N) is writing it
  /// …", or why the lock file cannot be made.
  explicit OutputLock(const std::string& path);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  /// The lock file.
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  int fd_ = -1;
};

}  // namespace magnus
