#include "app/ffmpeg.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace magnus {

std::string find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "";
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
    const std::string file = dir + "/" + program;
    struct stat st;
    if (::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(file.c_str(), X_OK) == 0) return file;
    start = end + 1;
  }
  return "";
}

std::string ffmpeg_program() {
  const std::string found = find_on_path("ffmpeg");
  if (found.empty())
    throw std::runtime_error("--movie: ffmpeg is not on PATH; the films are encoded by it (Debian: apt-get install ffmpeg)");
  return found;
}

int run_program(const std::string& program, const std::vector<std::string>& args, const std::string& log) {
  std::vector<std::string> all = {program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  const int err = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error(fmt::format("cannot start '{}': {}", program, std::strerror(err)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for '{}': {}", program, std::strerror(errno)));
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::vector<std::string> ffmpeg_film_args(const std::string& dir, int fps, const std::string& format,
                                          const std::string& out) {
  const std::string rate = std::to_string(fps);
  std::vector<std::string> a = {"-nostdin", "-hide_banner", "-loglevel", "error", "-y",
                                "-framerate", rate, "-i", dir + "/top_%05d.png",
                                "-framerate", rate, "-i", dir + "/bottom_%05d.png"};
  if (format == "gif") {
    // One palette for the whole film (the colour bar keeps its colours) and no dithering: the vorticity's
    // shades are flat, and a pixel's colour depends on itself alone.
    a.insert(a.end(), {"-filter_complex",
                       "[0:v][1:v]vstack=inputs=2,split[a][b];[a]palettegen=stats_mode=full[p];"
                       "[b][p]paletteuse=dither=none",
                       "-loop", "0", "-f", "gif", out});
  } else {
    a.insert(a.end(), {"-filter_complex", "[0:v][1:v]vstack=inputs=2,format=yuv420p", "-c:v", "libx264",
                       "-pix_fmt", "yuv420p", "-crf", "20", "-movflags", "+faststart", "-f", "mp4", out});
  }
  return a;
}

}  // namespace magnus
