#include "solver/memory.hpp"
#include "physics/checked_cast.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace magnus {

size_t available_bytes() {
  size_t avail = 0;
  std::ifstream mi("/proc/meminfo");
  std::string key;
  size_t value;
  std::string unit;
  while (mi >> key >> value) {
    std::getline(mi, unit);
    if (key == "MemAvailable:") avail = value * 1024;
  }
  // A cgroup (v2) limit, if any, less what the group already uses.
  std::ifstream lim("/sys/fs/cgroup/memory.max"), cur("/sys/fs/cgroup/memory.current");
  std::string l;
  size_t used = 0;
  if (lim >> l && l != "max" && cur >> used) {
    const size_t limit = std::stoull(l);
    const size_t left = limit > used ? limit - used : 0;
    if (avail == 0 || left < avail) avail = left;
  }
  return avail;
}

size_t parse_bytes(const std::string& text) {
  std::istringstream in(text);
  double v;
  std::string unit;
  if (!(in >> v) || !(v > 0) || !std::isfinite(v))
    throw std::invalid_argument("expected a size like 2G or 512M");
  in >> unit;
  double scale = 1;
  if (unit.empty() || unit == "B")
    scale = 1;
  else if (unit == "K" || unit == "KiB" || unit == "k")
    scale = 1024.0;
  else if (unit == "M" || unit == "MiB")
    scale = 1024.0 * 1024;
  else if (unit == "G" || unit == "GiB")
    scale = 1024.0 * 1024 * 1024;
  else if (unit == "T" || unit == "TiB")
    scale = 1024.0 * 1024 * 1024 * 1024;
  else
    throw std::invalid_argument("unknown unit '" + unit + "' (use K, M, G or T)");
  std::string rest;
  if (in >> rest) throw std::invalid_argument("expected a size like 2G or 512M");
  return saturate_cast<size_t>(v * scale);  // 1e300G: more than any machine has, not undefined behaviour
}

std::string format_bytes(size_t bytes) {
  char buf[64];
  const double b = double(bytes);
  if (b >= 1024.0 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.2f GiB", b / (1024.0 * 1024 * 1024));
  else if (b >= 1024.0 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f MiB", b / (1024.0 * 1024));
  else
    std::snprintf(buf, sizeof buf, "%.0f KiB", b / 1024.0);
  return buf;
}

void check_memory(size_t needed, size_t limit, const std::string& what) {
  const bool given = limit > 0;
  // Below 16 MiB the machine's free memory is not read (it costs ~40 µs, as much as a small solve): any
  // machine magnus runs on has that much. An explicit limit is always checked.
  if (!given && needed < kUncheckedBytes) return;
  if (!given) limit = available_bytes();
  if (limit == 0 || needed <= limit) return;
  throw std::runtime_error(what + " needs about " + format_bytes(needed) + ", more than " +
                           (given ? "--max-memory " : "the memory available, ") + format_bytes(limit) +
                           ": use a smaller grid" +
                           (what.find("cholmod") != std::string::npos ? " or solver.method = \"fft\"" : ""));
}

}  // namespace magnus
