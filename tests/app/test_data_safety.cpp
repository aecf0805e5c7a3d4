// No data loss: a magnus killed while it writes, a full disk, an unwritable place, and
// damaged or foreign files given to `magnus inspect`. Every test runs the magnus binary of this build
// (under scripts/sanitize.sh that is the sanitized one).
#include <fcntl.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "io/inspect.hpp"
#include "base/output_lock.hpp"
#include "io/report.hpp"
#include "run_child.hpp"
#include "support.hpp"

using namespace magnus;
namespace fs = std::filesystem;

namespace {

using test::lines;
using test::slurp;

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// test::magnus_cmd goes through the shell and waits; these tests need the child's PID (to kill it while it
// writes) and a file-size limit set between fork and exec (run_child.hpp).
using Child = test::Running;
using Outcome = test::Ended;

Child start(const std::vector<std::string>& args, const std::string& dir, rlim_t file_limit = 0) {
  return test::start_magnus(args, dir, "std", file_limit);
}

Outcome finish(const Child& c) { return test::wait_magnus(c); }

Outcome run_magnus(const std::vector<std::string>& args, const std::string& dir, rlim_t file_limit = 0) {
  return finish(start(args, dir, file_limit));
}

/// Names in dir other than the harness's own files.
std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name != "std.out" && name != "std.err") out.push_back(name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> temp_files(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& n : names_in(dir))
    if (n.find(".tmp-") != std::string::npos) out.push_back(n);
  return out;
}

const std::string case_path = std::string(MAGNUS_SOURCE_DIR) + "/cases/spin_ratio_1.toml";

/// A small real result at path (the "earlier result" that must survive).
void earlier_result(const std::string& path, const std::string& dir) {
  const Outcome o = run_magnus({"run", case_path, "-o", path, "-q", "--set", "grid.n_theta=32"}, dir);
  REQUIRE(o.exited);
  REQUIRE(o.status == 0);
}

/// `magnus inspect` on a file that is not a good result: a clean refusal, one line naming the file.
void require_refused(const std::string& path, const std::string& dir) {
  const Outcome o = run_magnus({"inspect", path}, dir);
  CAPTURE(path, o.err);
  REQUIRE(o.exited);  // never a signal (a crash)
  REQUIRE(o.status == 1);
  REQUIRE(lines(o.err) == 1);
  REQUIRE(o.err.rfind("magnus: error: ", 0) == 0);
  REQUIRE(o.err.find(fs::path(path).filename().string()) != std::string::npos);
}

/// Offset of the first occurrence of needle in hay (npos if none).
size_t find_bytes(const std::string& hay, const std::string& needle, size_t from = 0) {
  return hay.find(needle, from);
}

}  // namespace

TEST_CASE("SIGKILL while writing leaves the earlier result intact and no partial file", "[app][safety]") {
  const std::string dir = test::temp_dir("safety-kill");
  const std::string out = dir + "/r.h5";
  earlier_result(out, dir);
  const std::string before = slurp(out), before_xmf = slurp(dir + "/r.xmf");
  REQUIRE(before.size() > 1000);
  // A 100 MB result: killed once its temporary file exists, after 5 MB, and after 40 MB of it are written.
  const std::vector<std::string> big = {"run", case_path, "-o", out, "-q", "--set", "grid.n_theta=1024"};
  int killed_mid_write = 0;
  for (const uintmax_t written : {uintmax_t(0), uintmax_t(5) << 20, uintmax_t(40) << 20}) {
    const Child c = start(big, dir);
    const std::string tmp = dir + "/.r.h5.tmp-" + std::to_string(c.pid);
    bool seen = false;
    for (int k = 0; k < 60000 && !seen; ++k) {  // up to 60 s (a sanitized build is slow)
      std::error_code ec;
      const auto size = fs::file_size(tmp, ec);
      seen = !ec && size >= written && size > 0;
      if (!seen) {
        if (::waitpid(c.pid, nullptr, WNOHANG) == c.pid)
          FAIL("magnus ended before writing " << written << " bytes");
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
    REQUIRE(seen);
    ::kill(c.pid, SIGKILL);
    const Outcome o = finish(c);
    CAPTURE(written, o.err);
    if (o.exited) {
      // It finished between the look and the kill: then the new result must be complete.
      REQUIRE(o.status == 0);
      continue;
    }
    REQUIRE(o.status == SIGKILL);
    ++killed_mid_write;
    // The final name still holds the earlier result, byte for byte; the sidecar too.
    REQUIRE(slurp(out) == before);
    REQUIRE(slurp(dir + "/r.xmf") == before_xmf);
    // A killed process cannot remove its temporary file: it stays, under a name that is never the final one.
    REQUIRE(temp_files(dir) == std::vector<std::string>{".r.h5.tmp-" + std::to_string(c.pid)});
  }
  REQUIRE(killed_mid_write >= 2);
  // The next run to the same target removes the temporaries of writers that are gone.
  earlier_result(out, dir);
  REQUIRE(temp_files(dir).empty());
  REQUIRE(names_in(dir) == std::vector<std::string>{"r.h5", "r.xmf"});
  // ...but never those of a writer that is still running, which holds a lock on its temporary (here: this
  // test process). Its PID says nothing: one from another PID namespace (a container) looks dead here.
  const std::string live = dir + "/.r.h5.tmp-999999999";
  spit(live, "in progress");
  const int fd = ::open(live.c_str(), O_RDWR | O_CLOEXEC);
  REQUIRE(fd >= 0);
  REQUIRE(try_lock_file(fd));
  earlier_result(out, dir);
  REQUIRE(slurp(live) == "in progress");
  ::close(fd);  // the writer is gone: its temporary is stale, whatever PID it names (here a live one)
  const std::string mine = dir + "/.r.h5.tmp-" + std::to_string(::getpid());
  fs::rename(live, mine);
  earlier_result(out, dir);
  REQUIRE_FALSE(fs::exists(mine));
  REQUIRE(names_in(dir) == std::vector<std::string>{"r.h5", "r.xmf"});
}

TEST_CASE("a full disk gives one line naming the file, no partial output, the earlier result intact",
          "[app][safety]") {
  const std::string dir = test::temp_dir("safety-full");
  const std::string out = dir + "/r.h5";
  earlier_result(out, dir);
  const std::string before = slurp(out), before_xmf = slurp(dir + "/r.xmf");
  // The default case writes ~2.8 MB: fail its writes after 2 KB, 64 KB, 1 MB and 2.5 MB.
  for (const rlim_t limit : {rlim_t(2) << 10, rlim_t(64) << 10, rlim_t(1) << 20, rlim_t(5) << 19}) {
    const Outcome o = run_magnus({"run", case_path, "-o", out, "-q"}, dir, limit);
    CAPTURE(limit, o.err);
    REQUIRE(o.exited);  // not killed by SIGXFSZ or a crash in HDF5's clean-up at exit
    REQUIRE(o.status == 1);
    REQUIRE(lines(o.err) == 1);
    REQUIRE(o.err.find("'" + out + "'") != std::string::npos);
    REQUIRE(o.err.find("File too large") != std::string::npos);
    REQUIRE(slurp(out) == before);
    REQUIRE(slurp(dir + "/r.xmf") == before_xmf);
    REQUIRE(names_in(dir) == std::vector<std::string>{"r.h5", "r.xmf"});
  }
  // A new name under the same limit: nothing appears.
  const Outcome o = run_magnus({"run", case_path, "-o", dir + "/new.h5", "-q"}, dir, rlim_t(64) << 10);
  REQUIRE(o.status == 1);
  REQUIRE(names_in(dir) == std::vector<std::string>{"r.h5", "r.xmf"});
}

TEST_CASE("a full disk under magnus plot names the system's error, no PNG or temporary left",
          "[app][safety][plot]") {
  const std::string dir = test::temp_dir("safety-full-plot");
  earlier_result(dir + "/r.h5", dir);
  fs::create_directories(dir + "/pics");
  // A 900x700 picture is some 50 KB or more: fail its writes after 4 KB and 24 KB.
  for (const rlim_t limit : {rlim_t(4) << 10, rlim_t(24) << 10}) {
    const Outcome o = run_magnus({"plot", dir + "/r.h5", "-o", dir + "/pics", "--size", "900x700"}, dir, limit);
    CAPTURE(limit, o.err);
    REQUIRE(o.exited);
    REQUIRE(o.status == 1);
    REQUIRE(lines(o.err) == 1);
    CHECK(o.err.find("cannot write '" + dir + "/pics/r_streamlines.png': File too large") != std::string::npos);
    CHECK(o.err.find("PLplot produced no PNG") == std::string::npos);
    CHECK(fs::is_empty(dir + "/pics"));
  }
  // Without the limit the same command writes them.
  const Outcome ok = run_magnus({"plot", dir + "/r.h5", "-o", dir + "/pics", "--size", "900x700"}, dir);
  CAPTURE(ok.err);
  REQUIRE(ok.status == 0);
  CHECK(fs::file_size(dir + "/pics/r_streamlines.png") > (rlim_t(24) << 10));
}

TEST_CASE("an unwritable output place gives one line naming the file, before solving", "[app][safety]") {
  // Tests may run as root, for whom permission bits do not stop a write: use places no one can write.
  const std::string dir = test::temp_dir("safety-unwritable");
  spit(dir + "/plainfile", "x");
  fs::create_directory(dir + "/adir");
  for (const std::string& target : {dir + "/missing/r.h5", dir + "/plainfile/r.h5", dir + "/adir"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const Outcome o = run_magnus({"run", case_path, "-o", target, "-q", "--set", "grid.n_theta=1024"}, dir);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CAPTURE(target, o.err);
    REQUIRE(o.exited);
    REQUIRE(o.status == 1);
    REQUIRE(lines(o.err) == 1);
    REQUIRE(o.err.find("'" + target + "'") != std::string::npos);
    REQUIRE(seconds < 5.0);  // refused up front, not after a 100 MB solve
  }
  REQUIRE(names_in(dir) == std::vector<std::string>{"adir", "plainfile"});
  REQUIRE(fs::is_empty(dir + "/adir"));
}

TEST_CASE("inspect on truncated, corrupt, empty and non-files: one line, never a crash", "[app][safety]") {
  const std::string dir = test::temp_dir("safety-inspect");
  const std::string good = dir + "/good.h5";
  earlier_result(good, dir);
  const std::string bytes = slurp(good);
  const std::string reference = run_magnus({"inspect", good}, dir).out;
  REQUIRE(reference.find("read back intact") != std::string::npos);
  const std::string bad = dir + "/bad.h5";

  SECTION("truncated") {
    for (const size_t n : {size_t(1), size_t(8), size_t(100), size_t(2048), bytes.size() / 3,
                           bytes.size() / 2, bytes.size() - 512, bytes.size() - 1}) {
      spit(bad, bytes.substr(0, n));
      require_refused(bad, dir);
    }
  }
  SECTION("raw data overwritten in the middle: the checksum catches it") {
    // The bytes of /fields/psi as stored (little-endian doubles): find them in the file, damage them.
    hid_t f = H5Fopen(good.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    hid_t d = H5Dopen2(f, "/fields/psi", H5P_DEFAULT);
    std::vector<double> psi(size_t(H5Sget_simple_extent_npoints(H5Dget_space(d))));
    H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, psi.data());
    H5Dclose(d);
    H5Fclose(f);
    const std::string raw(reinterpret_cast<const char*>(psi.data() + psi.size() / 2), 64);
    const size_t at = find_bytes(bytes, raw);
    REQUIRE(at != std::string::npos);
    std::string damaged = bytes;
    for (size_t k = 0; k < 8; ++k) damaged[at + k] = char(damaged[at + k] ^ 0x5A);
    spit(bad, damaged);
    require_refused(bad, dir);
    REQUIRE(slurp(dir + "/std.err").find("damaged") != std::string::npos);
  }
  SECTION("metadata overwritten: superblock and every object header") {
    std::vector<size_t> at = {20};  // in the superblock, before its checksum
    for (size_t p = find_bytes(bytes, "OHDR"); p != std::string::npos; p = find_bytes(bytes, "OHDR", p + 1))
      at.push_back(p + 6);
    REQUIRE(at.size() > 10);
    for (size_t k = 0; k < at.size(); k += std::max<size_t>(1, at.size() / 16)) {  // at most ~16 of them
      const size_t p = at[k];
      std::string damaged = bytes;
      damaged[p] = char(damaged[p] ^ 0xFF);
      spit(bad, damaged);
      require_refused(bad, dir);
    }
  }
  SECTION("random bytes anywhere: refused, or (in unused bytes) the same report") {
    uint64_t rng = 0x9E3779B97F4A7C15ull;
    auto next = [&] { return rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17; };
    for (size_t k = 0; k < 40; ++k) {
      std::string damaged = bytes;
      const size_t p = (k * bytes.size()) / 40 + next() % (bytes.size() / 40 - 16);
      for (size_t j = 0; j < 16; ++j) damaged[p + j] = char(next());
      spit(bad, damaged);
      const Outcome o = run_magnus({"inspect", bad}, dir);
      CAPTURE(p, o.err);
      REQUIRE(o.exited);
      if (o.status == 0) {
        auto body = [](const std::string& s) { return s.substr(s.find('\n')); };  // without the file name
        REQUIRE(body(o.out) == body(reference));
      } else {
        REQUIRE(o.status == 1);
        REQUIRE(lines(o.err) == 1);
      }
    }
  }
  SECTION("empty file, directory, not a regular file, missing") {
    spit(bad, "");
    require_refused(bad, dir);
    fs::create_directory(dir + "/adir.h5");
    require_refused(dir + "/adir.h5", dir);
    spit(bad, std::string(4096, 'x'));
    require_refused(bad, dir);
    require_refused("/dev/null", dir);
    require_refused(dir + "/missing.h5", dir);
  }
}

TEST_CASE("inspect on foreign HDF5 files: one line, never a crash", "[app][safety]") {
  const std::string dir = test::temp_dir("safety-foreign");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  // Writes a file with an optional root attribute "format" made by add(file).
  auto make = [&](const std::string& name, const std::function<void(hid_t)>& add) {
    const std::string path = dir + "/" + name;
    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const hsize_t n = 4;
    const double v[4] = {1, 2, 3, 4};
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t d = H5Dcreate2(f, "data", H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Dclose(d);
    H5Sclose(s);
    add(f);
    REQUIRE(H5Fclose(f) >= 0);
    return path;
  };
  auto string_attr = [](hid_t obj, const char* name, const std::vector<const char*>& values, bool scalar) {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    const hsize_t n = values.size();
    const hid_t s = scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr);
    const hid_t a = H5Acreate2(obj, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, t, values.data());
    H5Aclose(a);
    H5Sclose(s);
    H5Tclose(t);
  };
  auto long_attr = [](hid_t obj, const char* name, std::vector<long> values) {
    const hsize_t n = values.size();
    const hid_t s = n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr);
    const hid_t a = H5Acreate2(obj, name, H5T_NATIVE_LONG, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_LONG, values.data());
    H5Aclose(a);
    H5Sclose(s);
  };
  const std::vector<std::string> foreign = {
      make("plain.h5", [](hid_t) {}),
      make("other_format.h5", [&](hid_t f) { string_attr(f, "format", {"something-else"}, true); }),
      make("format_int.h5", [&](hid_t f) { long_attr(f, "format", {7}); }),
      // An array where one string is expected: read into one pointer it would overrun the stack.
      make("format_array.h5",
           [&](hid_t f) {
             string_attr(f, "format", {"magnus-flow", "b", "c", "d"}, false);
           }),
      // Claims to be a result but holds nothing of one, or the wrong kinds of things.
      make("format_only.h5", [&](hid_t f) { string_attr(f, "format", {"magnus-flow"}, true); }),
      make("bad_version.h5",
           [&](hid_t f) {
             string_attr(f, "format", {"magnus-flow"}, true);
             long_attr(f, "format_version", {1, 2, 3, 4, 5, 6, 7, 8});
           }),
      make("bad_software.h5",
           [&](hid_t f) {
             string_attr(f, "format", {"magnus-flow"}, true);
             long_attr(f, "format_version", {1});
             long_attr(f, "software_version", {1});
           }),
  };
  for (const auto& path : foreign) require_refused(path, dir);
  REQUIRE(slurp(dir + "/std.err").find("bad_software.h5") != std::string::npos);
}

TEST_CASE("reading damaged files in-process throws one line and leaves no HDF5 object open",
          "[app][safety]") {
  const std::string dir = test::temp_dir("safety-inprocess");
  const std::string good = dir + "/good.h5";
  earlier_result(good, dir);
  const std::string bytes = slurp(good);
  REQUIRE(describe_result(good).find("read back intact") != std::string::npos);
  const ssize_t open_before = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  std::vector<std::string> damaged = {bytes.substr(0, bytes.size() / 2), bytes.substr(0, 100), std::string()};
  for (const size_t at :
       {bytes.size() / 2, bytes.size() / 3, bytes.find("OHDR") + 6, bytes.rfind("OHDR") + 6}) {
    std::string b = bytes;
    for (size_t k = 0; k < 8; ++k) b[at + k] = char(~b[at + k]);
    damaged.push_back(b);
  }
  size_t refused = 0;
  for (const auto& b : damaged) {
    spit(dir + "/bad.h5", b);
    try {
      describe_result(dir + "/bad.h5");
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      CAPTURE(what);
      REQUIRE(what.find('\n') == std::string::npos);
      REQUIRE(what.find("bad.h5") != std::string::npos);
      ++refused;
    }
    REQUIRE(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) == open_before);
  }
  REQUIRE(refused == damaged.size());
}

namespace {

/// run_magnus, but a child still running after `seconds` is killed and reported (a FIFO must never hang).
Outcome run_bounded(const std::vector<std::string>& args, const std::string& dir, int seconds = 60) {
  const Child c = start(args, dir);
  for (int k = 0; k < seconds * 20; ++k) {
    int raw = 0;
    const pid_t p = ::waitpid(c.pid, &raw, WNOHANG);
    if (p == c.pid)
      return {WIFEXITED(raw), WIFEXITED(raw) ? WEXITSTATUS(raw) : WTERMSIG(raw), slurp(c.out_path),
              slurp(c.err_path)};
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::kill(c.pid, SIGKILL);
  ::waitpid(c.pid, nullptr, 0);
  FAIL("magnus " << args[0] << " still running after " << seconds << " s (blocked on an output?)");
  return {};
}

/// A refusal: exit 1, one line on stderr naming the path.
void require_one_line_refusal(const Outcome& o, const std::string& path) {
  CAPTURE(o.err, o.out);
  REQUIRE(o.exited);
  REQUIRE(o.status == 1);
  REQUIRE(lines(o.err) == 1);
  REQUIRE(o.err.find(fs::path(path).filename().string()) != std::string::npos);
}

}  // namespace

TEST_CASE("outputs through a symlink replace its target and keep the link (compare --csv, run -o)",
          "[app][safety]") {
  const std::string dir = test::temp_dir("safety-links");
  earlier_result(dir + "/a.h5", dir);
  spit(dir + "/real.csv", "file,title,cl\nold.h5,,1\n");  // an earlier compare --csv
  fs::create_symlink("real.csv", dir + "/link.csv");
  const Outcome c = run_bounded({"compare", dir + "/a.h5", "--csv", dir + "/link.csv"}, dir);
  CAPTURE(c.err);
  REQUIRE(c.status == 0);
  REQUIRE(fs::is_symlink(dir + "/link.csv"));
  REQUIRE(slurp(dir + "/real.csv").rfind("file,title", 0) == 0);

  earlier_result(dir + "/real.h5", dir);
  fs::create_symlink("real.h5", dir + "/link.h5");
  const Outcome r =
      run_bounded({"run", case_path, "-o", dir + "/link.h5", "-q", "--set", "grid.n_theta=16"}, dir);
  CAPTURE(r.err);
  REQUIRE(r.status == 0);
  REQUIRE(fs::is_symlink(dir + "/link.h5"));
  REQUIRE(fs::is_regular_file(fs::symlink_status(dir + "/real.h5")));
  REQUIRE(slurp(dir + "/real.h5").compare(1, 3, "HDF") == 0);
  // The sidecar sits beside the name given, and names it (the link resolves for the viewer).
  REQUIRE(slurp(dir + "/link.xmf").find("link.h5:/mesh/") != std::string::npos);
  REQUIRE(temp_files(dir).empty());
}

TEST_CASE("a FIFO, a device or a directory as an output is refused in one line, untouched", "[app][safety]") {
  const std::string dir = test::temp_dir("safety-special");
  earlier_result(dir + "/a.h5", dir);
  // A FIFO: refused without opening it (opening would block with no reader).
  REQUIRE(::mkfifo((dir + "/fifo.csv").c_str(), 0644) == 0);
  REQUIRE(::mkfifo((dir + "/fifo.h5").c_str(), 0644) == 0);
  require_one_line_refusal(run_bounded({"compare", dir + "/a.h5", "--csv", dir + "/fifo.csv"}, dir, 20),
                           dir + "/fifo.csv");
  require_one_line_refusal(run_bounded({"run", case_path, "-o", dir + "/fifo.h5", "-q"}, dir, 20),
                           dir + "/fifo.h5");
  struct stat st;
  REQUIRE(::lstat((dir + "/fifo.csv").c_str(), &st) == 0);
  REQUIRE(S_ISFIFO(st.st_mode));
  REQUIRE(::lstat((dir + "/fifo.h5").c_str(), &st) == 0);
  REQUIRE(S_ISFIFO(st.st_mode));

  // A character device: as root, a device node of our own (root could rename over /dev/null itself).
  std::string device = "/dev/null";
  if (::geteuid() == 0) {
    device = dir + "/null";
    REQUIRE(::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);
  }
  require_one_line_refusal(run_bounded({"compare", dir + "/a.h5", "--csv", device}, dir, 20), device);
  REQUIRE(::lstat(device.c_str(), &st) == 0);
  REQUIRE(S_ISCHR(st.st_mode));

  // A directory.
  fs::create_directory(dir + "/sub");
  require_one_line_refusal(run_bounded({"compare", dir + "/a.h5", "--csv", dir + "/sub"}, dir, 20),
                           dir + "/sub");
  require_one_line_refusal(run_bounded({"run", case_path, "-o", dir + "/sub", "-q"}, dir, 20), dir + "/sub");
  REQUIRE(fs::is_directory(dir + "/sub"));
  REQUIRE(fs::is_empty(dir + "/sub"));
  REQUIRE(temp_files(dir).empty());
}

TEST_CASE("compare --csv - writes the CSV alone on stdout and creates no file named '-'",
          "[app][safety][compare]") {
  const std::string dir = test::temp_dir("safety-stdout");
  earlier_result(dir + "/a.h5", dir);
  const bool dash_before = fs::exists("-");
  const Outcome o = run_bounded({"compare", dir + "/a.h5", dir + "/a.h5", "--csv", "-"}, dir);
  CAPTURE(o.err);
  REQUIRE(o.status == 0);
  REQUIRE(o.out.rfind("file,title", 0) == 0);
  REQUIRE(o.out.find("magnus compare:") == std::string::npos);  // no table mixed into the CSV
  REQUIRE(lines(o.out) == 3);
  REQUIRE(o.err.empty());
  REQUIRE(fs::exists("-") == dash_before);
  REQUIRE_FALSE(fs::exists(dir + "/-"));
}

TEST_CASE("compare --csv /dev/stdout writes to the stream, never replaces what stdout is",
          "[app][safety][compare]") {
  const std::string dir = test::temp_dir("safety-devstdout");
  earlier_result(dir + "/a.h5", dir);
  // The harness sends stdout to a regular file: following /dev/stdout → /proc/self/fd/1 → that file and
  // renaming over it would lose the stream's own output; /dev/stdout means the stream, like "-".
  for (const char* name : {"/dev/stdout", "/proc/self/fd/1"}) {
    CAPTURE(name);
    const Outcome o = run_bounded({"compare", dir + "/a.h5", "--csv", name}, dir);
    CAPTURE(o.err);
    REQUIRE(o.status == 0);
    REQUIRE(o.out.rfind("file,title", 0) == 0);
    REQUIRE(lines(o.out) == 2);
  }
  // A FIFO or device reached through a link is refused like the FIFO or device itself.
  const std::string link = dir + "/null-link";
  fs::create_symlink("/dev/null", link);
  const Outcome o = run_bounded({"compare", dir + "/a.h5", "--csv", link}, dir);
  REQUIRE(o.status != 0);
  REQUIRE(o.err.find("it is a device") != std::string::npos);
  REQUIRE(fs::is_symlink(link));
}
