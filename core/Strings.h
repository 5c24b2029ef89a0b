// Small string helpers for parsing names and quoting input in messages, used in core and app.
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace armtrack {

/// s with ASCII letters lowered, for case-insensitive name matching.
inline std::string asciiLower(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// A cell or column name of an input file between double quotes for a message: bytes outside
/// printable ASCII as \xNN (a NUL would otherwise cut the message short), at most 40 bytes shown.
inline std::string quotedCell(std::string_view s) {
  constexpr std::size_t kShown = 40;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kShown; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c > 0x7e) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  out += '"';
  if (s.size() > kShown)
    out += " (" + std::to_string(s.size()) + " bytes, first " + std::to_string(kShown) + " shown)";
  return out;
}

}  // namespace armtrack
