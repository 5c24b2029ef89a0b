// A gtest fixture with a folder of its own under the system's temporary folder: named after the
// prefix, the process and the test (so parallel test processes never share one), emptied before
// each test and removed after it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace armtrack::test {

class TempDirTest : public ::testing::Test {
 protected:
  /// prefix: the folder name's start, e.g. "armtrack_cli_".
  explicit TempDirTest(std::string prefix) : m_prefix(std::move(prefix)) {}

  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Name/0"
    m_dir = std::filesystem::temp_directory_path() /
            (m_prefix + std::to_string(::getpid()) + "_" + name);
    std::filesystem::remove_all(m_dir);
    std::filesystem::create_directories(m_dir);
  }
  void TearDown() override {
    std::error_code ignored;  // a test that left a read-only file must not fail here
    std::filesystem::remove_all(m_dir, ignored);
  }

  std::filesystem::path path(const std::string& name) const { return m_dir / name; }

  std::filesystem::path m_dir;

 private:
  std::string m_prefix;
};

}  // namespace armtrack::test
