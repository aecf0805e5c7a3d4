#pragma once
// toml::parse without toml++ 3.3's undefined behaviour on some non-ASCII code points
// (marzer/tomlplusplus#190), and the UTF-8 helpers it needs. Used by the case-file parser only.
#include <toml++/toml.h>
#include <string>
#include <string_view>

namespace magnus::toml_safe {

/// Decodes one well-formed UTF-8 sequence at s[i] (length in *len); returns 0 with *len = 1 if malformed.
char32_t decode_utf8(std::string_view s, size_t i, size_t* len);

/// A parse error's description with the shielded code points swapped back.
std::string unshield(std::string_view s);

/// toml::parse without toml++'s undefined behaviour. Throws toml::parse_error (description shielded: pass it
/// through unshield()) or CaseError (a private-use code point of the swap range, named with `origin`).
toml::table parse_toml(const std::string& text, const std::string& origin);

}  // namespace magnus::toml_safe
