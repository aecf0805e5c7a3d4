#pragma once
// Memory guard, the general part: what the machine has, sizes in and out of text, and the one refusal
// before anything large is allocated (every model's estimates call check_memory).
#include <cstddef>
#include <string>

namespace magnus {

/// Memory this process may use: MemAvailable from /proc/meminfo, capped by the cgroup limit.
size_t available_bytes();

/// "2G", "512M", "1.5GiB", "800000000" → bytes. Throws std::invalid_argument on anything else.
size_t parse_bytes(const std::string& text);

/// "1.23 GiB".
std::string format_bytes(size_t bytes);

/// Estimates below this are not checked against available_bytes() (an explicit limit still applies), bytes.
constexpr size_t kUncheckedBytes = size_t(16) << 20;

/// Throws std::runtime_error with the estimate if `needed` exceeds `limit` (0: available_bytes(), read
/// only when needed ≥ kUncheckedBytes).
void check_memory(size_t needed, size_t limit, const std::string& what);

}  // namespace magnus
