#pragma once
// Number and column formatting shared by every text table and CSV that magnus prints or writes.
#include <string>

namespace magnus {

/// fmt spec applied to v, except that a fixed-point spec ("{:.5f}") of |v| >= 1e9 gives "{:.6g}" instead:
/// no figure runs to hundreds of digits (1e290 prints as 1e+290, not 291 digits and 5 decimals); and no sign
/// on a value that rounds to zero ("0.000", not "-0.000" or "-0"; "+0.000" with an explicit sign, "{:+.3f}").
std::string figure(double v, const char* spec);

/// A table cell: figure(v, spec); "—" for a non-finite (undefined) value.
std::string cell(double v, const char* spec);

/// A duration: "12.3 ms" below one second, else "1.23 s".
std::string ms(double seconds);

/// Display width of UTF-8 text in columns (every character magnus prints is one column wide).
size_t display_width(const std::string& s);

/// s padded with spaces on the left (right-aligned) or right (left-aligned) to w columns.
std::string pad_left(const std::string& s, size_t w);
std::string pad_right(const std::string& s, size_t w);

/// A number in a CSV: all 17 significant digits ("{:.17g}", reads back exactly), "0" for -0.
std::string csv_number(double v);

/// A CSV field, quoted when it holds a comma, a quote or a newline (RFC 4180).
std::string csv_field(const std::string& s);

}  // namespace magnus
