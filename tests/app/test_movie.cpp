// `magnus plot RESULT --movie FILM`: the film decoded by ffmpeg (one frame per snapshot, the size asked
// for, frames that differ, one colour range in every frame), and the one-line refusals that write nothing.
// ffmpeg is a declared dependency (scripts/setup.sh): its absence fails these tests, it does not skip them.
#include <sys/stat.h>
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/ffmpeg.hpp"
#include "app/run_child.hpp"
#include "io/hdf5_io.hpp"
#include "io/viscous_fixture.hpp"
#include "plot/film.hpp"
#include "plot/png_image.hpp"
#include "support.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

/// ffmpeg's (or ffprobe's) standard output for a film, through popen (test code; magnus itself uses no shell).
std::string tool_output(const std::string& command) {
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[1 << 16];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  REQUIRE(::pclose(p) == 0);
  return out;
}

/// "WxH" of the film's video stream.
std::string film_size(const std::string& film) {
  std::string s = tool_output("ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0:s=x '" +
                              film + "'");
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

/// Every frame of the film as it decodes, rgb24, width × height × 3 bytes each (no frame dropped or doubled).
std::vector<std::string> decode_frames(const std::string& film, PlotSize size) {
  const std::string raw = tool_output("ffmpeg -v error -nostdin -i '" + film +
                                      "' -fps_mode passthrough -f rawvideo -pix_fmt rgb24 -");
  const size_t frame = size_t(size.width) * size_t(size.height) * 3;
  REQUIRE(raw.size() % frame == 0);
  std::vector<std::string> frames;
  for (size_t at = 0; at < raw.size(); at += frame) frames.push_back(raw.substr(at, frame));
  return frames;
}

/// The pixels of rows y0 … y1 − 1, columns x0 … x1 − 1 of an rgb24 frame.
std::string region(const std::string& frame, PlotSize size, int x0, int x1, int y0, int y1) {
  std::string out;
  for (int y = y0; y < y1; ++y) out += frame.substr((size_t(y) * size.width + x0) * 3, size_t(x1 - x0) * 3);
  return out;
}

std::string region(const test::Image& img, int x0, int x1, int y0, int y1) {
  std::string out;
  for (int y = y0; y < y1; ++y)
    out.append(reinterpret_cast<const char*>(&img.rgb[(size_t(y) * img.width + x0) * 3]), size_t(x1 - x0) * 3);
  return out;
}

void require_ffmpeg() {
  INFO("ffmpeg is a declared dependency of magnus plot --movie: apt-get install ffmpeg (scripts/setup.sh)");
  REQUIRE_FALSE(find_on_path("ffmpeg").empty());
  REQUIRE_FALSE(find_on_path("ffprobe").empty());
}

/// The names in dir (the leftovers of a refused or finished command).
std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("magnus plot --movie: a GIF with one frame per snapshot, the size asked for, one colour range",
          "[app][plot][movie]") {
  require_ffmpeg();
  const std::string dir = test::temp_dir("movie-gif"), tmp = dir + "/tmp";
  fs::create_directories(tmp);
  const FlowResult r = test::viscous_result_by_hand(1.0, 32, 16, 5);
  write_result(r, dir + "/flow.h5");
  const PlotSize size{400, 320};
  ::setenv("TMPDIR", tmp.c_str(), 1);  // where the frames are drawn: empty again afterwards
  const test::Outcome o =
      test::magnus_cmd({"plot", dir + "/flow.h5", "--movie", dir + "/wake.gif", "--size", "400x320", "--fps", "5"}, dir);
  ::unsetenv("TMPDIR");
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out == dir + "/wake.gif\n");
  CHECK(names_in(tmp).empty());
  CHECK(film_size(dir + "/wake.gif") == "400x320");
  const std::vector<std::string> frames = decode_frames(dir + "/wake.gif", size);
  REQUIRE(frames.size() == r.viscous->snapshots.size());
  for (size_t k = 1; k < frames.size(); ++k) CHECK(frames[k] != frames[k - 1]);

  // Where the colour bar and its numbers are: the film's first frame drawn again by plot/film.
  const PlotWindow w = window_for(r, std::nullopt);
  const VorticityRange film = film_vorticity_range(r, w);
  const PlotFrame f = draw_film_frame(r, 0, w, film, size, dir + "/top.png", dir + "/bottom.png");
  REQUIRE_FALSE(f.colour_bar.empty());
  CHECK(f.bar_hi == Approx(film.limit));
  const int x0 = int(f.colour_bar.x0) - 2, x1 = size.width, y0 = std::max(0, int(f.colour_bar.y0) - 6),
            y1 = std::min(film_panel_sizes(size).first.height, int(f.colour_bar.y1) + 6);
  // The bar and its numbers are the same pixels in every frame…
  for (size_t k = 1; k < frames.size(); ++k)
    CHECK(region(frames[k], size, x0, x1, y0, y1) == region(frames[0], size, x0, x1, y0, y1));
  // …which is the film's one range: each snapshot's own range differs, and a frame drawn over its own
  // range has other numbers on its bar (the region sees the range).
  const VorticityRange own = vorticity_range(r.grid, {&r.viscous->snapshots[0].vorticity}, w);
  CHECK(own.limit != Approx(film.limit).epsilon(0.02));
  CHECK(vorticity_range(r.grid, {&r.viscous->snapshots[1].vorticity}, w).limit != Approx(own.limit).epsilon(0.02));
  plot_contour_field(vorticity_field_picture(r, r.viscous->snapshots[0].vorticity, w, own), dir + "/own.png",
                     film_panel_sizes(size).first);
  CHECK(region(test::read_png(dir + "/own.png"), x0, x1, y0, y1) != region(test::read_png(dir + "/top.png"), x0, x1, y0, y1));
}

TEST_CASE("magnus plot --movie: an H.264 MP4, one frame per snapshot, the size asked for", "[app][plot][movie]") {
  require_ffmpeg();
  const std::string dir = test::temp_dir("movie-mp4");
  write_result(test::viscous_result_by_hand(1.0, 32, 16, 4), dir + "/flow.h5");
  const test::Outcome o =
      test::magnus_cmd({"plot", dir + "/flow.h5", "--movie", dir + "/wake.mp4", "--size", "352x288", "-q"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.out.empty());
  CHECK(film_size(dir + "/wake.mp4") == "352x288");
  CHECK(tool_output("ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,pix_fmt -of csv=p=0 '" +
                    dir + "/wake.mp4'") == "h264,yuv420p\n");
  const std::vector<std::string> frames = decode_frames(dir + "/wake.mp4", {352, 288});
  REQUIRE(frames.size() == 4);
  for (size_t k = 1; k < frames.size(); ++k) CHECK(frames[k] != frames[k - 1]);
  // The film is marked as magnus's: the next --movie to the same name replaces it without --force.
  const std::string first = test::slurp(dir + "/wake.mp4");
  const test::Outcome again = test::magnus_cmd(
      {"plot", dir + "/flow.h5", "--movie", dir + "/wake.mp4", "--size", "352x288", "--fps", "6", "-q"}, dir);
  CAPTURE(again.err);
  REQUIRE(again.status == 0);
  CHECK(test::slurp(dir + "/wake.mp4") != first);
  CHECK(decode_frames(dir + "/wake.mp4", {352, 288}).size() == 4);
  std::vector<std::string> left = names_in(dir);
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"flow.h5", "flow.xmf", "stderr.txt", "stdout.txt", "wake.mp4"});
}

TEST_CASE("magnus plot --movie refuses bad input in one line and writes nothing", "[app][plot][movie]") {
  require_ffmpeg();
  const std::string dir = test::temp_dir("movie-refusals");
  write_result(test::viscous_result_by_hand(1.0, 32, 16, 3), dir + "/flow.h5");
  write_result(test::viscous_result_by_hand(1.0, 32, 16, 0), dir + "/still.h5");
  write_result(run_case(test::make_case(1.0, 32)), dir + "/potential.h5");
  std::ofstream(dir + "/a.toml") << "[cylinder]\nradius = 0.1\nspin_ratio = 1.0\n[flow]\nspeed = 10.0\n"
                                    "[grid]\nn_theta = 32\n";
  REQUIRE(test::magnus_cmd({"sweep", dir + "/a.toml", "--spin-ratio", "0:1:1", "-o", dir + "/sw.h5", "-q"}, dir)
              .status == 0);
  fs::create_directory(dir + "/folder.gif");
  REQUIRE(::mkfifo((dir + "/pipe.gif").c_str(), 0600) == 0);
  std::ofstream(dir + "/theirs.gif") << "someone else's film";
  const std::string empty_path = dir + "/no-programs";
  fs::create_directory(empty_path);

  struct Bad {
    std::vector<std::string> args;
    std::string says;
    std::string path = "";  ///< non-empty: run with PATH set to this
  };
  const std::string flow = dir + "/flow.h5", film = dir + "/film.gif";
  const std::vector<Bad> bad = {
      {{dir + "/still.h5", "--movie", film}, "has no snapshots: run with output.snapshots = N"},
      {{dir + "/potential.h5", "--movie", film}, "potential-flow result"},
      {{dir + "/sw.h5", "--movie", film}, "is a sweep file"},
      {{flow, "--movie", dir + "/film.avi"}, "must end in .mp4 or .gif"},
      {{flow, "--movie", dir + "/film.mp4", "--size", "321x240"}, "even width and height"},
      {{flow, "--movie", film, "--fps", "0"}, "--fps 0"},
      {{flow, "--movie", film, "--size", "400x250"}, "at least 320x256 pixels"},
      {{flow, "--movie", film, "-o", dir}, "excludes"},
      {{flow, "--movie", dir + "/folder.gif"}, "folder.gif"},
      {{flow, "--movie", dir + "/pipe.gif"}, "pipe.gif"},
      {{flow, "--movie", dir + "/theirs.gif"}, "not a file magnus wrote"},
      {{flow, "--movie", film}, "apt-get install ffmpeg", empty_path},
  };
  const std::vector<std::string> before = names_in(dir);
  for (const Bad& b : bad) {
    std::vector<std::string> args = {"plot"};
    args.insert(args.end(), b.args.begin(), b.args.end());
    const std::string old_path = std::getenv("PATH") ? std::getenv("PATH") : "";
    if (!b.path.empty()) ::setenv("PATH", b.path.c_str(), 1);
    const test::Outcome o = test::magnus_cmd(args, dir);
    ::setenv("PATH", old_path.c_str(), 1);
    CAPTURE(args, o.err);
    CHECK(o.status != 0);
    CHECK(test::one_line(o.err));
    CHECK(o.err.find(b.says) != std::string::npos);
    std::vector<std::string> now = names_in(dir);
    CHECK(now.size() == before.size());  // no film, no temporary file
  }
  CHECK(fs::is_directory(dir + "/folder.gif"));
  struct stat st;
  REQUIRE(::stat((dir + "/pipe.gif").c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(test::slurp(dir + "/theirs.gif") == "someone else's film");
}

TEST_CASE("magnus plot --movie stopped by SIGTERM or SIGINT leaves no film, no frames and no temporary file",
          "[app][plot][movie]") {
  require_ffmpeg();
  const std::string dir = test::temp_dir("movie-signal"), tmp = dir + "/tmp";
  fs::create_directories(tmp);
  write_result(test::viscous_result_by_hand(1.0, 32, 16, 60), dir + "/flow.h5");
  for (const int sig : {SIGTERM, SIGINT}) {
    CAPTURE(sig);
    ::setenv("TMPDIR", tmp.c_str(), 1);
    const test::Running c =
        test::start_magnus({"plot", dir + "/flow.h5", "--movie", dir + "/wake.gif", "--size", "400x320"}, dir);
    ::unsetenv("TMPDIR");
    // Signal once the second frame is being drawn (its first panel is there): the film is under way.
    bool drawing = false;
    for (int k = 0; k < 120000 && !drawing; ++k) {  // up to 2 minutes on a loaded machine
      for (const auto& e : fs::recursive_directory_iterator(tmp, fs::directory_options::skip_permission_denied))
        drawing = drawing || e.path().filename() == "top_00001.png";
      if (!drawing) {
        if (::waitpid(c.pid, nullptr, WNOHANG) != 0) FAIL("magnus ended before its second frame");
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
    REQUIRE(drawing);
    REQUIRE(::kill(c.pid, sig) == 0);
    const test::Ended e = test::wait_magnus(c);
    CAPTURE(e.err);
    CHECK(e.exited);
    CHECK(e.status == 128 + sig);
    CHECK(names_in(tmp).empty());
    std::vector<std::string> left = names_in(dir);
    std::sort(left.begin(), left.end());
    CHECK(left == std::vector<std::string>{"child.err", "child.out", "flow.h5", "flow.xmf", "tmp"});
  }
}
