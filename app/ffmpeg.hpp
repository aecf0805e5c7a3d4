#pragma once
// The encoder of the wake films: Debian's ffmpeg, run as a child process from an argument vector (no
// shell), its messages kept in a log file so that a failure can be reported in one line.
#include <string>
#include <vector>

namespace magnus {

/// The path of `program` found on PATH (an executable regular file), "" when there is none.
std::string find_on_path(const std::string& program);

/// The ffmpeg on PATH. Throws std::runtime_error with one line naming the Debian package when absent.
std::string ffmpeg_program();

/// Runs program with args (argv[1…]), stdin from /dev/null, stdout and stderr into `log`; waits for it.
/// Returns its exit status (128 + the signal when killed). Throws when it cannot be started.
int run_program(const std::string& program, const std::vector<std::string>& args, const std::string& log);

/// The ffmpeg arguments that encode a film from the frame images top_%05d.png (stacked above)
/// bottom_%05d.png in `dir`, at fps frames a second, to `out` in format "mp4" (H.264, yuv420p) or "gif"
/// (one palette for the whole film, no dithering, looping).
std::vector<std::string> ffmpeg_film_args(const std::string& dir, int fps, const std::string& format,
                                          const std::string& out);

}  // namespace magnus
