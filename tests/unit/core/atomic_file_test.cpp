// writeFileAtomically: the new bytes replace the old ones whole, the old version is kept as the
// backup when asked, permissions survive, and a folder or a missing folder is refused with an
// error that names the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <sys/stat.h>

#include "fixtures/core/atomic_file.h"

namespace haze {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("haze_atomic_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(AtomicFile, ReplacesWholeAndKeepsTheBackup) {
  const fs::path dir = freshDir("replace");
  const fs::path f = dir / "a.txt";
  ASSERT_TRUE(writeFileAtomically(f, "first", true).ok());
  EXPECT_EQ(slurp(f), "first");
  EXPECT_FALSE(fs::exists(backupPathFor(f)));  // nothing to back up yet
  ::chmod(f.c_str(), 0600);
  ASSERT_TRUE(writeFileAtomically(f, "second", true).ok());
  EXPECT_EQ(slurp(f), "second");
  EXPECT_EQ(slurp(backupPathFor(f)), "first");
  EXPECT_EQ(fs::status(f).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  ASSERT_TRUE(writeFileAtomically(f, "third", false).ok());
  EXPECT_EQ(slurp(backupPathFor(f)), "first");  // no backup asked: the old one stays as it was
  // No temporary file is left behind.
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.is_regular_file();
  EXPECT_EQ(entries, 2);
}

TEST(AtomicFile, RefusesFoldersAndNamesTheFile) {
  const fs::path dir = freshDir("refuse");
  Status s = writeFileAtomically(dir, "x", false);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().str().find(dir.string()), std::string::npos) << s.error().str();
  Status missing = writeFileAtomically(dir / "no" / "such" / "f.txt", "x", false);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().str().find("f.txt"), std::string::npos) << missing.error().str();
}

}  // namespace
}  // namespace haze
