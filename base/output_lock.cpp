#include "base/output_lock.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "base/atomic_file.hpp"

namespace magnus {

bool try_lock_file(int fd) {
  struct flock l {};
  l.l_type = F_WRLCK;
  l.l_whence = SEEK_SET;  // l_start = l_len = 0: the whole file, however long it grows
  return ::fcntl(fd, F_OFD_SETLK, &l) == 0;
}

namespace {

/// The PID a lock file records ("" if none can be read).
std::string recorded_pid(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string s = n > 0 ? std::string(buf, size_t(n)) : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s.find_first_not_of("0123456789") == std::string::npos ? s : "";
}

/// Whether fd still is the file at path (not removed or replaced by a releasing holder meanwhile).
bool still_at(int fd, const std::string& path) {
  struct stat a, b;
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev &&
         a.st_ino == b.st_ino;
}

}  // namespace

OutputLock::OutputLock(const std::string& path) : file_(output_target(path) + ".lock") {
  // A holder removes the file before it lets go: a lock taken on a removed file is no lock, so try again.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
      throw std::runtime_error(fmt::format("cannot write '{}': cannot make its lock file '{}': {}", path,
                                           file_, std::strerror(errno)));
    if (!try_lock_file(fd)) {
      const std::string pid = recorded_pid(fd);
      ::close(fd);
      throw std::runtime_error(fmt::format(
          "cannot write '{}': another magnus run ({}) is writing it (lock file '{}'); wait for it to end or "
          "give another -o",
          path, pid.empty() ? "PID unknown" : "PID " + pid, file_));
    }
    if (still_at(fd, file_)) {
      const std::string text = std::to_string(::getpid()) + "\n";
      // The PID only serves the message of a refused run: a lock without it still locks.
      if (::ftruncate(fd, 0) == 0) (void)!::pwrite(fd, text.data(), text.size(), 0);
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw std::runtime_error(fmt::format("cannot write '{}': its lock file '{}' keeps changing", path, file_));
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());  // while still held: a run that opened it meanwhile sees it gone and retries
  ::close(fd_);
}

}  // namespace magnus
