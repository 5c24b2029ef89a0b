// AtomicFile: the target holds either its old contents or the whole new file, and temporary files
// never stay behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/io/AtomicFile.h"
#include "tests/support/TempDirTest.h"

namespace armtrack {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public armtrack::test::TempDirTest {
 protected:
  AtomicFileTest() : TempDirTest("armtrack_atomic_") {}

  std::string read(const fs::path& p) const {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  int entries() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(m_dir)) ++n;
    return n;
  }
};

TEST_F(AtomicFileTest, CommitReplacesTheTargetAndLeavesNoTemporaryFile) {
  const fs::path target = m_dir / "out.csv";
  std::ofstream(target) << "old";
  {
    AtomicFile f(target);
    EXPECT_EQ(f.temporary().parent_path(), m_dir);
    f.write("new ");
    f.write("contents\n");
    EXPECT_EQ(read(target), "old");  // untouched until commit
    f.commit();
  }
  EXPECT_EQ(read(target), "new contents\n");
  EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFileTest, WithoutCommitTheOldFileStaysAndTheTemporaryGoes) {
  const fs::path target = m_dir / "out.csv";
  std::ofstream(target) << "old";
  {
    AtomicFile f(target);
    f.write("half a fi");
    f.finish();  // even finished, an unpublished file is discarded
  }
  EXPECT_EQ(read(target), "old");
  EXPECT_EQ(entries(), 1);
}

TEST_F(AtomicFileTest, FailuresNameTheTargetAndTheReason) {
  const fs::path target = m_dir / "missing" / "out.csv";
  try {
    AtomicFile f(target);
    FAIL() << "a file in a missing directory was created";
  } catch (const AtomicFileError& e) {
    EXPECT_EQ(e.target(), target);
    EXPECT_NE(e.message().find("cannot create temporary file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("No such file or directory"), std::string::npos) << e.what();
  }
  AtomicFile f(m_dir / "a.csv");
  f.finish();
  EXPECT_THROW(f.write("late"), AtomicFileError);
}

TEST_F(AtomicFileTest, ARenameOntoADirectoryFailsAndKeepsIt) {
  const fs::path target = m_dir / "dir";
  fs::create_directories(target / "inside");
  AtomicFile f(target);
  f.write("x");
  EXPECT_THROW(f.commit(), AtomicFileError);
  EXPECT_TRUE(fs::is_directory(target / "inside"));
}

}  // namespace
}  // namespace armtrack
