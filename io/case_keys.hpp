#pragma once
// The keys a case file may hold, and the suggestions for a misspelt one (near spellings and synonyms
// only, never a key of another meaning). Used by io/case_file.
#include <map>
#include <string>
#include <vector>

namespace magnus {

/// Every valid key, by section ("" for the top level), in file order.
const std::map<std::string, std::vector<std::string>>& case_key_table();

/// "section.key" ("key" at the top level).
std::string key_name(const std::string& section, const std::string& key);

/// User input as quoted in a message: at most `max` characters (whole UTF-8 characters), then "…" when cut.
std::string cut_input(const std::string& s, size_t max = 60);

/// Levenshtein distance between a and b (insertions, deletions, substitutions).
size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace magnus
