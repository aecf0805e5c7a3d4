#pragma once
// Case files: TOML with in-code defaults, range checks, loud failure on conflicts.
#include <stdexcept>
#include <string>
#include <vector>
#include "physics/scene.hpp"

namespace magnus {

/// A case-file problem: one line naming the file and the key.
struct CaseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The lowest Re = U·2a/ν a navier-stokes case accepts: below it the viscous (Oseen) length D/Re is over
/// 100 D, creeping flow whose forces depend on the outer radius R (D/Re beyond R) rather than on the scene.
constexpr double kNsMinReynolds = 0.01;

/// Parse a case from TOML text; `origin` names it in messages. `overrides` are "section.key=value"
/// strings (the value as in TOML; a bare word is a string). Throws CaseError.
Case parse_case(const std::string& toml_text, const std::string& origin,
                const std::vector<std::string>& overrides = {});

/// With --set on a key of the scene (model, cylinder, flow, circulation) the case's title may describe
/// another scene ("spin ratio 1" run at α = 0): the title becomes "<model> flow, <case file> with --set
/// k=v, …" (and source_text follows), so the summary, the file and the pictures say what ran. A --set
/// title=… is kept as given; other keys (grid, time, output) keep the case's title.
void retitle_for_overrides(Case& c, const std::string& case_path, const std::vector<std::string>& sets);

/// Read and parse a case file. Throws CaseError (missing file, bad TOML, bad keys or values).
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {});

/// The resolved case as TOML: every key of its model with its final value. The viscosity is written as given
/// (flow.viscosity or flow.reynolds); a navier-stokes case adds [model], [time] and the snapshot keys and
/// leaves out potential flow's [circulation], domain.far_field and [solver].
std::string to_toml(const Case& c);

/// Every valid "section.key".
const std::vector<std::string>& case_keys();

/// The valid key a misspelt one most likely means: a synonym (flow.velocity → flow.speed) or a near spelling
/// (within 2 edits and a third of the length, in the key's own section); "" if none, and always "" for a key
/// that means something else (cylinder.span is not cylinder.spin).
std::string nearest_key(const std::string& key);

/// What follows "unknown key K" in a message: " (did you mean X?)", else " (keys of [section]: …)", else "".
std::string unknown_key_hint(const std::string& key);

}  // namespace magnus
