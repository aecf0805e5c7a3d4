// The base layer alone (magnus_tests_base links nothing above it): an output appears only when complete,
// what is not a regular file is never a target, and only magnus's own files (or empty ones) may be replaced.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "base/atomic_file.hpp"
#include "base/output_owner.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

/// A fresh empty directory for one test.
std::string scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("magnus-base-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The smallest PNG signature + IHDR chunk (13 data bytes, CRC not checked by the marker).
std::string tiny_png() {
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0d", 4) + "IHDR" + std::string(13, '\0') + std::string(4, '\0');
  png += std::string("\0\0\0\0", 4) + "IEND" + std::string(4, '\0');
  return png;
}

}  // namespace

TEST_CASE("atomic file: the target changes only on commit, and no temporary is left either way", "[base]") {
  const std::string dir = scratch("atomic"), path = dir + "/out.png", old = mark_png(tiny_png());
  std::ofstream(path, std::ios::binary) << old;  // a PNG magnus wrote: it may be replaced
  {
    AtomicFile f(path);
    write_text(f, "new, never committed");
    CHECK(fs::exists(f.temp()));
    CHECK(slurp(path) == old);
  }
  CHECK(slurp(path) == old);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  {
    AtomicFile f(path);
    write_text(f, "new");
    f.commit();
  }
  CHECK(slurp(path) == "new");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  // A file magnus did not write is refused before anything is written, left as it was, no temporary made.
  const std::string notes = dir + "/notes.txt";
  std::ofstream(notes) << "my notes\n";
  CHECK_THROWS_WITH(AtomicFile{notes}, Catch::Contains("not a file magnus wrote"));
  CHECK(slurp(notes) == "my notes\n");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 2);
  fs::remove_all(dir);
}

TEST_CASE("atomic file: a directory or a FIFO is never a target, and the message names it", "[base]") {
  const std::string dir = scratch("special");
  CHECK_THROWS_WITH(output_target(dir), Catch::Contains(dir));
  const std::string fifo = dir + "/pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(check_writable(fifo), Catch::Contains("pipe"));
  CHECK(fs::is_fifo(fifo));
  fs::remove_all(dir);
}

TEST_CASE("output owner: empty files and magnus's marked PNGs may be replaced, other files not", "[base]") {
  const std::string dir = scratch("owner");
  const std::string empty = dir + "/empty.png", mine = dir + "/mine.png", theirs = dir + "/theirs.png",
                    text = dir + "/notes.txt";
  std::ofstream(empty).close();
  std::ofstream(mine, std::ios::binary) << mark_png(tiny_png());
  std::ofstream(theirs, std::ios::binary) << tiny_png();
  std::ofstream(text) << "my notes\n";
  CHECK(not_a_magnus_output(empty).empty());
  CHECK(not_a_magnus_output(mine).empty());
  CHECK_FALSE(not_a_magnus_output(theirs).empty());
  CHECK_FALSE(not_a_magnus_output(text).empty());
  CHECK(not_a_magnus_output(dir + "/absent").empty());
  CHECK_THROWS_WITH(check_replaceable(text, text), Catch::Contains("--force"));
  set_replace_any_file(true);
  CHECK_NOTHROW(check_replaceable(text, text));
  set_replace_any_file(false);
  CHECK(mark_png("not a png") == "not a png");
  fs::remove_all(dir);
}

TEST_CASE("output owner: a film magnus marked (GIF comment, MP4 last box) may be replaced, others not", "[base]") {
  const std::string dir = scratch("owner-film");
  // A GIF: header, a 1×1 screen with a 2-colour global table, one image, the trailer.
  const std::string gif = std::string("GIF89a\x01\x00\x01\x00\x80\x00\x00", 13) + std::string("\0\0\0\xff\xff\xff", 6) +
                          std::string("\x2c\0\0\0\0\x01\0\x01\0\0\x02\x02\x44\x01\0\x3b", 16);
  // An MP4's first box (ftyp), then a box of media data.
  const std::string mp4 = std::string("\0\0\0\x10" "ftypisom\0\0\x02\0", 16) + std::string("\0\0\0\x0c" "mdat\1\2\3\4", 12);
  for (const auto& [name, bytes] : {std::pair<std::string, std::string>{"a.gif", gif}, {"a.mp4", mp4}}) {
    const std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    CAPTURE(name);
    CHECK_FALSE(not_a_magnus_output(path).empty());
    REQUIRE(mark_film_file(path));
    CHECK(not_a_magnus_output(path).empty());
    std::ifstream in(path, std::ios::binary);
    const std::string marked((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(marked.size() > bytes.size());
    CHECK(marked.compare(0, 6, bytes, 0, 6) == 0);  // still a GIF, still an MP4 (its ftyp first)
  }
  // A GIF with someone else's comment, an MP4 whose last box is not magnus's, and plain text: not films.
  std::string other = gif;
  other.insert(19, std::string("\x21\xfe\x05" "other\0", 9));
  std::ofstream(dir + "/b.gif", std::ios::binary) << other;
  std::ofstream(dir + "/b.mp4", std::ios::binary) << mp4 + std::string("\0\0\0\x0c" "freeabcd", 12);
  CHECK_FALSE(not_a_magnus_output(dir + "/b.gif").empty());
  CHECK_FALSE(not_a_magnus_output(dir + "/b.mp4").empty());
  std::ofstream(dir + "/c.txt") << "magnus wrote this, it says\n";
  CHECK_FALSE(mark_film_file(dir + "/c.txt"));
  fs::remove_all(dir);
}
