#pragma once
// magnus as a child process that the test signals: faults are injected from outside (SIGKILL, SIGINT,
// SIGTERM at a moment the test chooses by watching the run's files), never by the program itself.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "io/hdf5_io.hpp"
#include "support.hpp"

namespace magnus::test {

/// A magnus started by start_magnus: its PID and where its stdout and stderr go.
struct Running {
  pid_t pid = -1;
  std::string out_path, err_path;
};

/// How it ended: exited (status = exit status) or killed by a signal (status = the signal).
struct Ended {
  bool exited = false;
  int status = 0;
  std::string out, err;
};

/// Start magnus with args, stdout and stderr into dir/NAME.out and dir/NAME.err. file_limit > 0 sets
/// RLIMIT_FSIZE (bytes) and ignores SIGXFSZ, so a write past the limit fails with EFBIG as on a full disk
/// instead of killing magnus.
inline Running start_magnus(const std::vector<std::string>& args, const std::string& dir,
                            const std::string& name = "child", rlim_t file_limit = 0) {
  Running c{-1, dir + "/" + name + ".out", dir + "/" + name + ".err"};
  std::vector<std::string> all = {MAGNUS_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  c.pid = ::fork();
  REQUIRE(c.pid >= 0);
  if (c.pid == 0) {  // only async-signal-safe calls until exec
    const int out = ::open(c.out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(c.err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (file_limit > 0) {
      const rlimit lim{file_limit, file_limit};
      ::signal(SIGXFSZ, SIG_IGN);
      if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) ::_exit(126);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return c;
}

/// Wait for the child to end.
inline Ended wait_magnus(const Running& c) {
  int raw = 0;
  REQUIRE(::waitpid(c.pid, &raw, 0) == c.pid);
  return {WIFEXITED(raw), WIFEXITED(raw) ? WEXITSTATUS(raw) : WTERMSIG(raw), slurp(c.out_path),
          slurp(c.err_path)};
}

/// The time (s) of the checkpoint at path, or -1 while there is none that reads.
inline double checkpoint_time(const std::string& path) {
  try {
    const ResultFile f(path, std::vector<std::string>{"magnus-checkpoint"});
    return f.attr_double("/state", "t");
  } catch (const std::exception&) {
    return -1.0;
  }
}

/// Watch the child's checkpoint file (every millisecond, reading it again whenever it is replaced) until
/// it holds a time ≥ t_min (s), then send sig at once. Fails the test if the child ends first. Returns the
/// time seen.
inline double signal_after_checkpoint(const Running& c, const std::string& ckpt, double t_min, int sig) {
  // A replaced file is a new inode (whose number may be the old one's again) with a new modification time.
  ino_t seen_ino = 0;
  long seen_ns = -1;
  for (int k = 0; k < 120000; ++k) {  // up to 2 minutes (a sanitized build on a loaded machine)
    struct stat st;
    if (::stat(ckpt.c_str(), &st) == 0 && (st.st_ino != seen_ino || st.st_mtim.tv_nsec != seen_ns)) {
      seen_ino = st.st_ino;
      seen_ns = st.st_mtim.tv_nsec;
      const double t = checkpoint_time(ckpt);
      if (t >= t_min) {
        REQUIRE(::kill(c.pid, sig) == 0);
        return t;
      }
    }
    if (::waitpid(c.pid, nullptr, WNOHANG) == c.pid)
      FAIL("magnus ended before a checkpoint at t >= " << t_min);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  FAIL("no checkpoint at t >= " << t_min << " in 2 minutes");
  return -1.0;
}

}  // namespace magnus::test
