#include "tests/support.hpp"

#include <filesystem>
#include <unistd.h>

namespace magnus::test {

std::string temp_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path p = fs::temp_directory_path() / ("magnus-test-" + std::to_string(::getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

}  // namespace magnus::test
