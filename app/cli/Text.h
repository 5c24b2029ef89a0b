// Small text helpers shared by the armtrack-cli commands.
#pragma once

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace armtrack::cli {

/// s between double quotes, for naming values in messages.
inline std::string inQuotes(std::string_view s) {
  return "\"" + std::string(s) + "\"";
}

/// A cell of an input file between double quotes for a message: bytes outside printable ASCII as
/// \xNN (a NUL would otherwise cut the message short), at most 40 bytes shown.
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

/// The shortest decimal form of v that reads back to the same double (std::to_chars).
inline std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// v with a fixed number of decimals, for tables.
inline std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

/// Whether a and b name the same file (after resolving what exists of them); false on error.
inline bool samePath(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec1, ec2;
  const std::filesystem::path ca = std::filesystem::weakly_canonical(a, ec1);
  const std::filesystem::path cb = std::filesystem::weakly_canonical(b, ec2);
  return !ec1 && !ec2 && ca == cb;
}

}  // namespace armtrack::cli
