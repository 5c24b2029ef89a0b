// What tests look at on disk: a file's permission bits and the names in a folder.
#pragma once

#include <sys/stat.h>

#include <filesystem>
#include <set>
#include <string>

namespace armtrack::test {

/// The permission bits of p (e.g. 0600); 0xFFFF when p is missing (never a mode).
inline unsigned modeOf(const std::filesystem::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) return 0xFFFF;
  return st.st_mode & 0777u;
}

/// The names in folder dir.
inline std::set<std::string> namesIn(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.insert(e.path().filename().string());
  return names;
}

}  // namespace armtrack::test
