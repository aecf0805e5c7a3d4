#include "io/case_keys.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "io/case_file.hpp"

namespace magnus {

const std::map<std::string, std::vector<std::string>>& case_key_table() {
  static const std::map<std::string, std::vector<std::string>> s = {
      {"", {"title"}},
      {"model", {"flow"}},
      {"cylinder", {"radius", "spin", "spin_ratio", "rpm", "span"}},
      {"flow", {"speed", "direction", "course", "density", "pressure", "viscosity", "reynolds"}},
      {"circulation", {"model", "value"}},
      {"domain", {"outer_radius", "far_field", "absorbing_layer", "absorbing_strength"}},
      {"grid", {"n_theta", "n_r", "spacing", "tolerance", "wall_refinement", "wall_layer", "refine"}},
      {"solver", {"method", "stencil", "advection_order", "advection_order_xi", "wall_closure", "implicit_rotation"}},
      {"time", {"mode", "end", "dt", "cfl", "mean_tolerance", "stop_on_drift", "checkpoint_interval"}},
      {"output", {"file", "fields", "compression", "snapshots", "snapshot_interval"}},
  };
  return s;
}

std::string cut_input(const std::string& s, size_t max) {
  size_t chars = 0, i = 0;
  for (; i < s.size(); ++i)
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 && chars++ == max) break;
  return i < s.size() ? s.substr(0, i) + "…" : s;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string key_name(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

const std::vector<std::string>& case_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& [sec, names] : case_key_table())
      for (const auto& n : names) k.push_back(key_name(sec, n));
    return k;
  }();
  return keys;
}

namespace {

/// Keys one letter apart that mean different things: a typo equally near both is not guessed.
const std::pair<const char*, const char*> kConfusable[] = {{"cylinder.spin", "cylinder.span"}};

}  // namespace

std::string nearest_key(const std::string& key) {
  // Synonyms of a valid key: the one suggestion that is not a near spelling.
  static const std::map<std::string, std::string> aliases = {{"flow.velocity", "flow.speed"},
                                                             {"flow.u", "flow.speed"},
                                                             {"flow.rho", "flow.density"},
                                                             {"cylinder.omega", "cylinder.spin"},
                                                             {"cylinder.alpha", "cylinder.spin_ratio"},
                                                             {"cylinder.a", "cylinder.radius"},
                                                             {"flow.nu", "flow.viscosity"},
                                                             {"flow.re", "flow.reynolds"},
                                                             {"cylinder.length", "cylinder.span"},
                                                             {"cylinder.height", "cylinder.span"},
                                                             {"flow.angle", "flow.direction"},
                                                             {"flow.heading", "flow.course"},
                                                             {"model", "model.flow"},
                                                             {"flow.model", "model.flow"}};
  if (const auto it = aliases.find(key); it != aliases.end()) return it->second;
  // The edit distance is at least the difference in length, and no valid key is longer than 24 characters:
  // a key this long is never near one (and a megabyte key would cost seconds).
  if (key.size() > 64) return "";
  // Near spellings only: within 2 edits and a third of the length, compared in the key's own section when it
  // names a valid one ("flow.velocity" is 4 edits from "flow.density": no suggestion).
  const size_t dot = key.find('.');
  const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
  const bool known_section = case_key_table().count(section) > 0 && !section.empty();
  std::string best;
  size_t best_d = std::string::npos;
  for (const auto& k : case_keys()) {
    const size_t kdot = k.find('.');
    const std::string ksec = kdot == std::string::npos ? "" : k.substr(0, kdot), tail = k.substr(kdot + 1);
    size_t d, len;
    if (known_section) {
      if (ksec != section) continue;
      d = edit_distance(key.substr(dot + 1), tail), len = key.size() - dot - 1;
    } else if (dot == std::string::npos) {
      d = edit_distance(key, tail), len = key.size();  // a bare key: its section was left out
    } else {
      d = edit_distance(key, k), len = key.size();
    }
    if (d <= 2 && 3 * d <= len && d < best_d) {
      best_d = d, best = k;
    } else if (d == best_d && !best.empty()) {
      // Equally near two keys of different meaning ("cylinder.spen": spin or span?): no guess.
      for (const auto& [x, y] : kConfusable)
        if ((best == x && k == y) || (best == y && k == x)) return "";
    }
  }
  return best;
}

std::string unknown_key_hint(const std::string& key) {
  const std::string near = nearest_key(key);
  if (!near.empty()) return fmt::format(" (did you mean {}?)", near);
  const size_t dot = key.find('.');
  if (dot == std::string::npos) return "";
  const auto sec = case_key_table().find(key.substr(0, dot));
  if (sec == case_key_table().end() || sec->first.empty()) return "";
  std::string list;
  for (const auto& k : sec->second) list += (list.empty() ? "" : ", ") + k;
  return fmt::format(" (keys of [{}]: {})", sec->first, list);
}

}  // namespace magnus
