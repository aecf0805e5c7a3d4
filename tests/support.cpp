#include "support.hpp"

#include <sys/wait.h>

#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace magnus::test {

std::string line_of(const std::string& text, const std::string& label) {
  for (size_t start = 0, nl; start < text.size(); start = nl + 1) {
    nl = text.find('\n', start);
    if (nl == std::string::npos) nl = text.size();
    if (text.compare(start, label.size(), label) == 0) return text.substr(start, nl - start);
  }
  return "";
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == s.size() - 1; }

Outcome magnus_cmd(std::vector<std::string> head, const std::vector<std::string>& tail, const std::string& dir) {
  head.insert(head.end(), tail.begin(), tail.end());
  return magnus_cmd(head, dir);
}

bool refused(const Outcome& o, const std::string& expect) {
  return o.status != 0 && one_line(o.err) && o.err.find(expect) != std::string::npos;
}

std::string temp_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path p = fs::temp_directory_path() / ("magnus-test-" + std::to_string(::getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

namespace {
std::string quote(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}
}  // namespace

Outcome magnus_cmd(const std::vector<std::string>& args, const std::string& dir) {
  std::string cmd = quote(MAGNUS_EXE);
  for (const auto& a : args) cmd += " " + quote(a);
  cmd += " >" + quote(dir + "/stdout.txt") + " 2>" + quote(dir + "/stderr.txt");
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128, slurp(dir + "/stdout.txt"), slurp(dir + "/stderr.txt")};
}

size_t lines(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

std::pair<unsigned long, unsigned long> png_size(const std::string& path) {
  const std::string b = slurp(path);
  if (b.size() < 100 || b.compare(1, 3, "PNG") != 0 || b.compare(12, 4, "IHDR") != 0) return {0, 0};
  if (b.compare(b.size() - 8, 4, "IEND") != 0) return {0, 0};
  auto be32 = [&](size_t at) {
    const auto* u = reinterpret_cast<const unsigned char*>(b.data()) + at;
    return (unsigned long)u[0] << 24 | (unsigned long)u[1] << 16 | (unsigned long)u[2] << 8 | u[3];
  };
  return {be32(16), be32(20)};
}

int run_script(const std::string& interpreter, const std::string& dir, const std::string& script,
               const std::vector<std::string>& args, std::string* output) {
  std::ofstream(dir + "/check.py") << script;
  std::string cmd = interpreter + " '" + dir + "/check.py'";
  for (const auto& a : args) cmd += " '" + a + "'";
  const int status = std::system((cmd + " >'" + dir + "/out.txt' 2>&1").c_str());
  if (output) *output = slurp(dir + "/out.txt");
  return status;
}

}  // namespace magnus::test
