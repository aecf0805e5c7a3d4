#pragma once
// `magnus inspect`: what a result file holds, as text.
#include <string>

namespace magnus {

/// What a result file holds (magnus inspect). Throws std::runtime_error with one line.
std::string describe_result(const std::string& path);

}  // namespace magnus
