#pragma once
// Parsing a case from text in the io tests: the case and the one-line message it is refused with.
#include <string>
#include <vector>

#include "io/case_file.hpp"

namespace magnus::test {

/// parse_case(text) as if from the file "test.toml", with the --set overrides sets.
inline Case parse(const std::string& text, const std::vector<std::string>& sets = {}) {
  return parse_case(text, "test.toml", sets);
}

/// The message parse_case throws for text ("" if it parses).
inline std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse(text, sets);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace magnus::test
