#include "base/atomic_file.hpp"
#include "base/output_owner.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "base/output_lock.hpp"

namespace magnus {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(fmt::format("cannot write '{}': {}", path, why));
}

/// What kind of non-regular file st is ("" for a regular file).
const char* special_kind(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "it is a directory";
  if (S_ISFIFO(st.st_mode)) return "it is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(st.st_mode)) return "it is a socket, not a regular file";
  if (!S_ISREG(st.st_mode)) return "it is not a regular file";
  return "";
}

/// Removes temporary files of earlier writers of target (".NAME.tmp-PID[-N]" beside it) that no writer
/// holds: a writer locks its temporary for as long as it lives (try_lock_file), and the kernel drops the
/// lock of a killed one, which cannot remove its own. A PID says nothing here: in another PID namespace
/// (a container, unshare) a live writer's PID looks dead.
void remove_stale_temps(const std::string& target) {
  const std::string dir = dir_of(target), prefix = "." + base_of(target) + ".tmp-";
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  std::vector<std::string> found;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string tail = name.substr(prefix.size());
    if (tail.size() <= 16 && tail.find_first_not_of("0123456789-") == std::string::npos)
      found.push_back(name);
  }
  ::closedir(d);
  for (const auto& name : found) {
    const std::string full = dir + "/" + name;
    struct stat st, at;
    if (::lstat(full.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    const int fd = ::open(full.c_str(), O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    if (try_lock_file(fd) && ::fstat(fd, &at) == 0 && ::lstat(full.c_str(), &st) == 0 &&
        at.st_ino == st.st_ino && at.st_dev == st.st_dev)
      ::unlink(full.c_str());
    ::close(fd);
  }
}

}  // namespace

std::string dir_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

std::string base_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool is_stdout(const std::string& path) {
  return path == "-" || path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1";
}

std::string output_target(const std::string& path) {
  if (path.empty()) fail(path, "empty file name");
  // What the path finally names, links followed (a pipe or socket behind /proc/self/fd/N has no path of
  // its own to follow): anything but a regular file is refused.
  struct stat final_st;
  if (::stat(path.c_str(), &final_st) == 0 && *special_kind(final_st)) fail(path, special_kind(final_st));
  std::string target = path;
  for (int hops = 0;; ++hops) {
    struct stat st;
    if (::lstat(target.c_str(), &st) != 0) return target;  // does not exist yet: created there
    if (!S_ISLNK(st.st_mode)) {
      const char* kind = special_kind(st);
      if (*kind) fail(path, kind);
      return target;
    }
    if (hops == 40) fail(path, "too many levels of symbolic links");
    std::error_code ec;
    const std::filesystem::path link = std::filesystem::read_symlink(target, ec);
    if (ec) fail(path, ec.message());
    target = link.is_absolute() ? link.string() : dir_of(target) + "/" + link.string();
  }
}

void check_writable(const std::string& path) {
  if (path.empty() || is_stdout(path)) return;
  const std::string target = output_target(path);
  if (base_of(target).empty()) fail(path, "the name is a directory");
  const std::string dir = dir_of(target);
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) fail(path, fmt::format("directory '{}' does not exist", dir));
  if (!S_ISDIR(st.st_mode)) fail(path, fmt::format("'{}' is not a directory", dir));
  if (::access(dir.c_str(), W_OK) != 0) fail(path, fmt::format("directory '{}' is not writable", dir));
  if (::access(target.c_str(), F_OK) == 0 && ::access(target.c_str(), W_OK) != 0)
    fail(path, "the existing file is not writable");
  check_replaceable(path, target);
}

void check_file_writable(const std::string& path, const char* what) {
  if (!path.empty() && is_stdout(path))
    fail(path, fmt::format("{} cannot go to standard output (only CSV and JSON can): name a file", what));
  check_writable(path);
}

void check_distinct_paths(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  namespace fs = std::filesystem;
  auto key = [](const std::string& p) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(fs::path(p), ec);
    return ec ? fs::absolute(p).lexically_normal().string() : c.string();
  };
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].empty() || is_stdout(outputs[i])) continue;
    const std::string o = key(outputs[i]);
    for (const auto& in : inputs)
      if (!in.empty() && key(in) == o) fail(outputs[i], fmt::format("it would overwrite the input '{}'", in));
    for (size_t j = 0; j < i; ++j)
      if (!outputs[j].empty() && key(outputs[j]) == o)
        fail(outputs[i], "another output of this command has the same name");
  }
}

AtomicFile::AtomicFile(const std::string& path) : path_(path), target_(output_target(path)) {
  if (base_of(target_).empty()) fail(path, "the name is a directory");
  check_replaceable(path, target_);
  remove_stale_temps(target_);
  const std::string stem = dir_of(target_) + "/." + base_of(target_) + ".tmp-" + std::to_string(::getpid());
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp_ = attempt ? stem + "-" + std::to_string(attempt) : stem;
    const int fd = ::open(temp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(path, std::strerror(errno));
    if (fd < 0) continue;
    // Locked while this object lives: the sweep of another writer leaves it alone. A sweep that got to it
    // between the open and the lock may have removed it: then another name.
    struct stat a, b;
    if (try_lock_file(fd) && ::fstat(fd, &a) == 0 && ::lstat(temp_.c_str(), &b) == 0 &&
        a.st_ino == b.st_ino && a.st_dev == b.st_dev) {
      lock_fd_ = fd;
      return;
    }
    ::close(fd);
  }
  fail(path, "no free temporary name beside it");
}

AtomicFile::~AtomicFile() {
  if (!committed_) ::unlink(temp_.c_str());
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

void AtomicFile::commit() {
  // The target may have become something else since the checks (a FIFO made meanwhile): look again.
  struct stat st;
  if (::lstat(target_.c_str(), &st) == 0 && *special_kind(st)) fail(path_, special_kind(st));
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail(path_, std::strerror(errno));
  committed_ = true;
  ::close(lock_fd_);
  lock_fd_ = -1;
}

void write_text(AtomicFile& f, const std::string& text) {
  FILE* out = std::fopen(f.temp().c_str(), "wb");
  if (!out) fail(f.path(), std::strerror(errno));
  errno = 0;
  const bool wrote = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  const int err = errno;
  const bool closed = std::fclose(out) == 0;
  if (!wrote || !closed) fail(f.path(), err ? std::strerror(err) : std::strerror(errno ? errno : EIO));
}

void write_text_output(const std::string& path, const std::string& text) {
  if (is_stdout(path)) {
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      throw std::runtime_error("cannot write to standard output: " + std::string(std::strerror(errno)));
    return;
  }
  AtomicFile f(path);
  write_text(f, text);
  f.commit();
}

}  // namespace magnus
