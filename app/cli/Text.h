// Small text helpers shared by the armtrack-cli commands.
#pragma once

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "core/Strings.h"

namespace armtrack::cli {

/// s between double quotes, for naming values in messages.
inline std::string inQuotes(std::string_view s) {
  return "\"" + std::string(s) + "\"";
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

/// s as one cell of a Markdown table: '|' escaped.
inline std::string tableCell(std::string_view s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

/// Whether a and b name the same file (after resolving what exists of them); false on error.
inline bool samePath(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec1, ec2;
  const std::filesystem::path ca = std::filesystem::weakly_canonical(a, ec1);
  const std::filesystem::path cb = std::filesystem::weakly_canonical(b, ec2);
  return !ec1 && !ec2 && ca == cb;
}

}  // namespace armtrack::cli
