// Small string helpers for parsing names in core (methods, sides).
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

}  // namespace armtrack
