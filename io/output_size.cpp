#include "io/output_size.hpp"

#include <fmt/core.h>
#include <sys/statvfs.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "postproc/fields.hpp"
#include "solver/memory.hpp"

namespace magnus {

size_t estimated_output_bytes(long n_r, long n_theta, int fields) {
  return 8 * size_t(n_r) * size_t(n_theta) * size_t(fields + 2) + 8 * (size_t(n_r) + 6 * size_t(n_theta));
}

std::optional<size_t> free_bytes_for(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  struct statvfs s {};
  if (::statvfs(dir.c_str(), &s) != 0) return std::nullopt;
  return size_t(s.f_bavail) * size_t(s.f_frsize);
}

void check_disk_space(const std::string& path, size_t needed, size_t free_bytes) {
  if (needed > free_bytes)
    throw std::runtime_error(fmt::format("{}: the result needs about {}, but only {} is free there", path,
                                         format_bytes(needed), format_bytes(free_bytes)));
}

void check_output_space(const Case& c, const std::string& path) {
  const FieldSelection sel = select_fields(c.output.fields, c.model);
  int fields = 2 * c.output.snapshots;  // each snapshot: ψ and ζ
  for (bool on : sel.on) fields += on;
  const GridShape g = grid_shape(c.grid);
  std::optional<size_t> free_bytes = free_bytes_for(path);
  if (const char* injected = std::getenv("MAGNUS_TEST_FREE_BYTES"))
    free_bytes = size_t(std::strtoull(injected, nullptr, 10));
  if (free_bytes) check_disk_space(path, estimated_output_bytes(g.n_r, g.n_theta, fields), *free_bytes);
}

}  // namespace magnus
