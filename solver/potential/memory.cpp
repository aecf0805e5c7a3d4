#include "solver/potential/memory.hpp"
#include "physics/checked_cast.hpp"

#include "mesh/polar_grid.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace magnus {

size_t solver_bytes(const DiscreteOperator& op, Method method) {
  return solver_bytes(op.n_r, op.n_theta, op.far_field, op.stencil, method);
}

size_t solver_bytes(double n_r, double n, FarField far_field, StencilKind stencil, Method method) {
  const bool exact = far_field == FarField::exact;
  const double L = exact ? n_r - 1 : n_r - 2, n_unknowns = L * n + (exact ? 0 : 1), m = n / 2 + 1;
  if (method == Method::fft) return size_t(std::min(8.0 * 2 * L * m + 16.0 * L * m + 64.0 * n, 1e19));
  const double nnz_a =
      (stencil == StencilKind::nine_point ? 5.0 : 3.0) * n_unknowns + (exact ? n * n / 2 : 1.0);
  const double triplets = 24.0 * nnz_a, matrix = 16.0 * nnz_a;
  const double fill = 4.0 * n_unknowns * std::log2(std::max(n_unknowns, 2.0)) + (exact ? n * n / 2 : 0.0);
  return size_t(std::min(triplets + matrix + 10.0 * fill + 64.0 * n_unknowns, 1e19));
}

void check_grid_memory(const GridRequest& grid, StencilKind stencil, Method method, int fields,
                       size_t limit) {
  const GridShape s = grid_shape(grid);
  const double nr = double(s.n_r), n = double(s.n_theta);
  const double bytes =
      double(solver_bytes(nr, n, grid.far_field, stencil, method)) + 8.0 * nr * n * (4 + fields);
  check_memory(size_t(std::min(bytes, 1e19)), limit,
               "the " + std::string(to_string(method)) + " solve on " + std::to_string(s.n_theta) + " × " +
                   std::to_string(s.n_r) + " with " + std::to_string(fields) +
                   (fields == 1 ? " field" : " fields"));
}

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
