#include "app/movie.hpp"

#include <stdlib.h>

#include <csignal>

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/ffmpeg.hpp"
#include "app/run_viscous.hpp"
#include "base/atomic_file.hpp"
#include "base/output_owner.hpp"
#include "io/hdf5_io.hpp"
#include "io/result_reader.hpp"
#include "plot/film.hpp"

namespace magnus {

namespace {

namespace fs = std::filesystem;

/// "mp4" or "gif" from the film's name (any case), else a one-line refusal.
std::string film_format(const std::string& movie) {
  std::string ext = fs::path(movie).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".mp4" && ext != ".gif")
    throw std::invalid_argument(
        fmt::format("--movie '{}': the film's name must end in .mp4 or .gif", movie));
  return ext.substr(1);
}

/// --fps, --size (at least kMinFilmSize; even for .mp4) and the target (writable, replaceable), in one line each.
void check_film_options(const std::string& movie, const std::string& format, PlotSize size, int fps) {
  if (fps < 1 || fps > kMaxFps)
    throw std::invalid_argument(fmt::format("--fps {}: expected 1 to {} frames a second", fps, kMaxFps));
  if (format == "mp4" && (size.width % 2 != 0 || size.height % 2 != 0))
    throw std::invalid_argument(fmt::format(
        "--size {}x{}: an .mp4 film needs an even width and height (H.264, yuv420p)", size.width, size.height));
  if (size.width < kMinFilmSize.width || size.height < kMinFilmSize.height)
    throw std::invalid_argument(fmt::format("--size {}x{}: a film's frame needs at least {}x{} pixels", size.width,
                                            size.height, kMinFilmSize.width, kMinFilmSize.height));
  check_file_writable(movie, "--movie");
  check_replaceable(movie, output_target(movie));  // before the frames are drawn, not after
}

/// The result of `path` if it is a navier-stokes result with snapshots and a force history; else one line.
FlowResult film_result(const std::string& path) {
  bool sweep = false;
  try {
    sweep = ResultFile(path, {"magnus-sweep"}).format() == "magnus-sweep";
  } catch (const std::exception&) {
    sweep = false;  // not a sweep: the result reader says what it is
  }
  if (sweep)
    throw std::runtime_error(fmt::format(
        "--movie: '{}' is a sweep file; a film needs a navier-stokes result with snapshots", path));
  FlowResult r = read_result(path);
  if (!r.viscous)
    throw std::runtime_error(fmt::format(
        "--movie: '{}' is a potential-flow result; a film needs a navier-stokes result with snapshots", path));
  if (r.viscous->snapshots.empty())
    throw std::runtime_error(
        fmt::format("--movie: '{}' has no snapshots: run with output.snapshots = N (N frames)", path));
  if (r.viscous->history.empty())
    throw std::runtime_error(fmt::format("--movie: '{}' has no /history (the forces beside the wake)", path));
  return r;
}

/// A private directory (mode 0700) for the frames, removed with everything in it on destruction.
struct FrameDir {
  std::string path;
  FrameDir() {
    const fs::path base = std::getenv("TMPDIR") && *std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp";
    std::string name = (base / "magnus-film-XXXXXX").string();
    if (!::mkdtemp(name.data()))
      throw std::runtime_error(fmt::format("--movie: cannot make a temporary directory in '{}'", base.string()));
    path = name;
  }
  ~FrameDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  FrameDir(const FrameDir&) = delete;
  FrameDir& operator=(const FrameDir&) = delete;
};

volatile std::sig_atomic_t g_film_signal = 0;  // SIGINT or SIGTERM received while the film is made (0: none)

extern "C" void on_film_signal(int sig) { g_film_signal = sig; }

/// While this lives, SIGINT and SIGTERM are noted instead of ending the program, so that stop() can
/// unwind: the frames' directory and the film's temporary file are then removed, and no film is written.
struct FilmSignals {
  FilmSignals() {
    g_film_signal = 0;
    previous_int = std::signal(SIGINT, on_film_signal);
    previous_term = std::signal(SIGTERM, on_film_signal);
    if (previous_int == SIG_IGN) std::signal(SIGINT, SIG_IGN);  // a background job's Ctrl-C stays ignored
  }
  ~FilmSignals() {
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
  }
  /// Throws Interrupted (exit status 128 + the signal) once a signal came.
  static void stop() {
    if (g_film_signal) throw Interrupted{int(g_film_signal)};
  }
  void (*previous_int)(int) = SIG_DFL;
  void (*previous_term)(int) = SIG_DFL;
};

/// The last non-empty line of a log file ("" when none).
std::string last_line(const std::string& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

/// ffmpeg encodes the frames in dir to `movie`, through a temporary file beside it renamed when complete.
void encode_film(const std::string& ffmpeg, const std::string& dir, const std::string& movie,
                 const std::string& format, int fps) {
  AtomicFile out(movie);
  const std::string log = dir + "/ffmpeg.log";
  const int status = run_program(ffmpeg, ffmpeg_film_args(dir, fps, format, out.temp()), log);
  FilmSignals::stop();  // Ctrl-C reaches ffmpeg too: it stops, and no film is written
  if (status != 0) {
    const std::string why = last_line(log);
    throw std::runtime_error(fmt::format("--movie '{}': ffmpeg failed (exit status {}){}{}", movie, status,
                                         why.empty() ? "" : ": ", why));
  }
  std::error_code ec;
  if (fs::file_size(out.temp(), ec) == 0 || ec)
    throw std::runtime_error(fmt::format("--movie '{}': ffmpeg wrote nothing", movie));
  if (!mark_film_file(out.temp()))  // so that the next --movie to this name may replace it
    throw std::runtime_error(fmt::format("--movie '{}': cannot mark the film as magnus's", movie));
  out.commit();
}

}  // namespace

MovieOutcome make_movie(const std::string& path, const std::string& movie, PlotSize size,
                        const std::optional<PlotWindow>& window, int fps) {
  const std::string format = film_format(movie);
  check_film_options(movie, format, size, fps);
  check_distinct_paths({path}, {movie});
  const std::string ffmpeg = ffmpeg_program();
  const FlowResult r = film_result(path);
  MovieOutcome o;
  o.window = window_for(r, window);
  o.range = film_vorticity_range(r, o.window);
  o.size = size;
  o.frames = r.viscous->snapshots.size();
  const FilmSignals signals;
  const FrameDir dir;
  for (size_t k = 0; k < o.frames; ++k) {
    FilmSignals::stop();
    const PlotFrame f = draw_film_frame(r, k, o.window, o.range, size, fmt::format("{}/top_{:05d}.png", dir.path, k),
                                        fmt::format("{}/bottom_{:05d}.png", dir.path, k));
    if (k == 0) o.vorticity = f;
  }
  encode_film(ffmpeg, dir.path, movie, format, fps);
  return o;
}

}  // namespace magnus
