#include "io/text_format.hpp"

#include <fmt/core.h>

#include <cmath>

namespace magnus {

std::string figure(double v, const char* spec) {
  const std::string sp = spec;
  const bool fixed =
      sp.size() >= 2 && sp[sp.size() - 1] == '}' && (sp[sp.size() - 2] == 'f' || sp[sp.size() - 2] == 'F');
  std::string s = fmt::format(fmt::runtime(fixed && std::fabs(v) >= 1e9 ? "{:.6g}" : spec), v);
  // A value that rounds to zero carries no sign: "0.00000", not "-0.00000" (round-off below the last digit).
  // With an explicit sign ("{:+.5f}") zero keeps its "+".
  if (std::isfinite(v) && s[0] == '-' && s.find_first_of("123456789", 1) == std::string::npos) {
    if (sp.find('+') != std::string::npos)
      s[0] = '+';
    else
      s.erase(0, 1);
  }
  return s;
}

std::string csv_number(double v) { return figure(v, "{:.17g}"); }

std::string cell(double v, const char* spec) { return std::isfinite(v) ? figure(v, spec) : "—"; }

std::string ms(double seconds) {
  return seconds < 1.0 ? fmt::format("{:.3g} ms", seconds * 1e3) : fmt::format("{:.3g} s", seconds);
}

size_t display_width(const std::string& s) {
  size_t n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  return n;
}

std::string pad_left(const std::string& s, size_t w) {
  const size_t n = display_width(s);
  return std::string(w > n ? w - n : 0, ' ') + s;
}

std::string pad_right(const std::string& s, size_t w) {
  const size_t n = display_width(s);
  return s + std::string(w > n ? w - n : 0, ' ');
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

}  // namespace magnus
