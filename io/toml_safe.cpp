#include "io/toml_safe.hpp"

#include <fmt/core.h>

#include "io/case_file.hpp"

namespace magnus::toml_safe {

namespace {

// toml++ 3.3 (Debian 12) reaches __builtin_unreachable() — undefined behaviour — when its whitespace test
// meets some non-ASCII code points outside a string or comment ("title = Über", "[Ü]", "a = [ψ]", "\Ü" in a
// """ string: https://github.com/marzer/tomlplusplus/issues/190, fixed upstream after 3.4). The parser never
// sees them: each is swapped for a private-use code point that toml++ treats the same way (a non-ASCII
// character that is neither whitespace nor allowed in a bare key), and swapped back in what the parse
// returns.
bool toml_ub_codepoint(char32_t c) {
  // The ranges where toml++'s is_non_ascii_horizontal_whitespace() has no case (blocks 0, 11, 63 of 0x3FA).
  return (c >= 0xA1 && c <= 0x499) || (c >= 0x2D1E && c <= 0x3117 && c != 0x3000) ||
         (c >= 0xFAC6 && c <= 0xFEFE);
}
constexpr char32_t shield_offset = 0xF0000;  // plane 15, private use: 0xF00A1 ... 0xFFEFE

}  // namespace

char32_t decode_utf8(std::string_view s, size_t i, size_t* len) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const auto cont = [&](size_t k) { return i + k < s.size() && (b(k) & 0xC0) == 0x80; };
  *len = 1;
  const unsigned c0 = b(0);
  if (c0 >= 0xC2 && c0 <= 0xDF && cont(1)) {
    *len = 2;
    return char32_t(((c0 & 0x1F) << 6) | (b(1) & 0x3F));
  }
  if (c0 >= 0xE0 && c0 <= 0xEF && cont(1) && cont(2)) {
    const char32_t c = char32_t(((c0 & 0x0F) << 12) | ((b(1) & 0x3F) << 6) | (b(2) & 0x3F));
    if (c < 0x800 || (c >= 0xD800 && c <= 0xDFFF)) return 0;
    *len = 3;
    return c;
  }
  if (c0 >= 0xF0 && c0 <= 0xF4 && cont(1) && cont(2) && cont(3)) {
    const char32_t c =
        char32_t(((c0 & 0x07) << 18) | ((b(1) & 0x3F) << 12) | ((b(2) & 0x3F) << 6) | (b(3) & 0x3F));
    if (c < 0x10000 || c > 0x10FFFF) return 0;
    *len = 4;
    return c;
  }
  return 0;
}

namespace {

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += char(c);
  } else if (c < 0x800) {
    out += char(0xC0 | (c >> 6));
    out += char(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += char(0xE0 | (c >> 12));
    out += char(0x80 | ((c >> 6) & 0x3F));
    out += char(0x80 | (c & 0x3F));
  } else {
    out += char(0xF0 | (c >> 18));
    out += char(0x80 | ((c >> 12) & 0x3F));
    out += char(0x80 | ((c >> 6) & 0x3F));
    out += char(0x80 | (c & 0x3F));
  }
}

/// Maps every code point c in s with from(c) to to(c); malformed bytes are left for toml++ to reject.
template <class From, class To>
std::string map_codepoints(std::string_view s, From from, To to, bool* changed = nullptr) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    size_t len;
    const char32_t c = decode_utf8(s, i, &len);
    if (len > 1 && from(c)) {
      append_utf8(out, to(c));
      if (changed) *changed = true;
    } else {
      out.append(s.substr(i, len));
    }
    i += len;
  }
  return out;
}

}  // namespace

std::string unshield(std::string_view s) {
  return map_codepoints(
      s, [](char32_t c) { return c > shield_offset && toml_ub_codepoint(c - shield_offset); },
      [](char32_t c) { return c - shield_offset; });
}

namespace {

/// A copy of a parsed value with every string and key unshielded.
void unshield_into(const toml::node& n, toml::array& out);
toml::table unshield_table(const toml::table& t) {
  toml::table out;
  for (auto&& [k, v] : t) {
    const std::string key = unshield(k.str());
    if (const auto* sub = v.as_table())
      out.insert(key, unshield_table(*sub));
    else if (const auto* arr = v.as_array()) {
      toml::array a;
      for (const auto& e : *arr) unshield_into(e, a);
      out.insert(key, std::move(a));
    } else if (const auto* str = v.as_string())
      out.insert(key, unshield(str->get()));
    else
      v.visit([&](const auto& value) { out.insert(key, value); });
  }
  return out;
}
void unshield_into(const toml::node& n, toml::array& out) {
  if (const auto* sub = n.as_table())
    out.push_back(unshield_table(*sub));
  else if (const auto* arr = n.as_array()) {
    toml::array a;
    for (const auto& e : *arr) unshield_into(e, a);
    out.push_back(std::move(a));
  } else if (const auto* str = n.as_string())
    out.push_back(unshield(str->get()));
  else
    n.visit([&](const auto& value) { out.push_back(value); });
}

}  // namespace

toml::table parse_toml(const std::string& text, const std::string& origin) {
  bool changed = false;
  // Private-use code points of the swap range cannot be told apart from swapped ones: refuse them.
  map_codepoints(
      text, [](char32_t c) { return c > shield_offset && toml_ub_codepoint(c - shield_offset); },
      [&](char32_t c) -> char32_t {
        throw CaseError(fmt::format("{}: unsupported character U+{:X} (private use)", origin, uint32_t(c)));
      });
  const std::string safe = map_codepoints(
      text, toml_ub_codepoint, [](char32_t c) { return c + shield_offset; }, &changed);
  toml::table t = toml::parse(safe, origin);
  return changed ? unshield_table(t) : t;
}

}  // namespace magnus::toml_safe
