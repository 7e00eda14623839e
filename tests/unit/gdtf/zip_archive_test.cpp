// ZipArchive: reading entries back, and every kind of hostile archive refused with a clear error
// (not a zip, a bomb by ratio and by total size, too many entries, unsafe names, a forged size).
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "fixtures/gdtf.h"
#include "fixtures/core/zip_archive.h"
#include "unit/gdtf/zip_builder.h"

namespace haze {
namespace {

using test::TempDir;
using test::writeZip;

TEST(ZipArchive, ReadsEntriesBackByName) {
  TempDir dir("read");
  std::string big(100000, 'x');
  for (std::size_t i = 0; i < big.size(); i += 7) big[i] = static_cast<char>('a' + i % 26);
  ASSERT_TRUE(writeZip(dir / "a.zip", {{"description.xml", "<GDTF/>"}, {"wheels/g.png", big, true}, {"deep/x.bin", big}}));
  auto zip = ZipArchive::open(dir / "a.zip");
  ASSERT_TRUE(zip.ok()) << zip.error().str();
  ASSERT_EQ(zip->entries().size(), 3u);
  EXPECT_EQ(zip->entries()[1].name, "wheels/g.png");
  EXPECT_EQ(zip->entries()[1].sizeBytes, big.size());
  auto a = zip->read("description.xml");
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(std::string(a->begin(), a->end()), "<GDTF/>");
  auto b = zip->read("deep/x.bin");
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(std::string(b->begin(), b->end()), big);
  auto c = zip->read("WHEELS/G.PNG");  // case-insensitive fallback
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->size(), big.size());
  auto missing = zip->read("nothing.txt");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("no entry 'nothing.txt'"), std::string::npos);
}

TEST(ZipArchive, RefusesAFileThatIsNotAZip) {
  TempDir dir("nozip");
  test::writeFile(dir / "x.gdtf", "this is a text file, not a zip archive at all\n");
  auto zip = ZipArchive::open(dir / "x.gdtf");
  ASSERT_FALSE(zip.ok());
  EXPECT_EQ(zip.error().file, (dir / "x.gdtf").string());
  EXPECT_NE(zip.error().message.find("not a valid zip"), std::string::npos) << zip.error().str();
  auto g = loadGdtf(dir / "x.gdtf");
  ASSERT_FALSE(g.ok());
  EXPECT_NE(g.error().str().find("not a valid zip"), std::string::npos);
  test::writeFile(dir / "empty.gdtf", "");
  EXPECT_FALSE(loadGdtf(dir / "empty.gdtf").ok());
  EXPECT_FALSE(loadGdtf(dir / "does-not-exist.gdtf").ok());
}

TEST(ZipArchive, RefusesABombByCompressionRatio) {
  TempDir dir("ratio");
  // 32 MiB of zeros deflate to about 32 KiB: a ratio near 1000:1.
  ASSERT_TRUE(writeZip(dir / "bomb.gdtf", {{"description.xml", std::string(32u << 20, '\0')}}));
  EXPECT_LT(std::filesystem::file_size(dir / "bomb.gdtf"), 1u << 20);
  auto g = loadGdtf(dir / "bomb.gdtf");
  ASSERT_FALSE(g.ok());
  EXPECT_NE(g.error().message.find("zip bomb"), std::string::npos) << g.error().str();
  EXPECT_NE(g.error().message.find("ratio"), std::string::npos) << g.error().str();
}

TEST(ZipArchive, RefusesABombByTotalAndEntrySize) {
  TempDir dir("total");
  // Random-looking data does not compress, so the ratio check passes; the size limits catch it.
  std::string noise(3u << 20, '\0');
  std::uint32_t x = 12345;
  for (char& c : noise) {
    x = x * 1664525u + 1013904223u;
    c = static_cast<char>(x >> 24);
  }
  ASSERT_TRUE(writeZip(dir / "big.zip", {{"a", noise}, {"b", noise}, {"c", noise}}));
  ZipLimits limits;
  limits.maxTotalBytes = 8u << 20;
  auto total = ZipArchive::open(dir / "big.zip", limits);
  ASSERT_FALSE(total.ok());
  EXPECT_EQ(total.error().place, "entry 2");
  EXPECT_NE(total.error().message.find("in all"), std::string::npos) << total.error().str();
  limits.maxEntryBytes = 2u << 20;
  auto entry = ZipArchive::open(dir / "big.zip", limits);
  ASSERT_FALSE(entry.ok());
  EXPECT_EQ(entry.error().place, "entry 0");
  EXPECT_NE(entry.error().message.find("per-entry limit"), std::string::npos) << entry.error().str();
  EXPECT_TRUE(ZipArchive::open(dir / "big.zip").ok());  // the default limits allow 9 MiB
}

TEST(ZipArchive, RefusesTooManyEntries) {
  TempDir dir("many");
  std::vector<test::ZipItem> items;
  const ZipLimits defaults;
  for (std::uint64_t i = 0; i <= defaults.maxEntries; ++i) items.push_back({"f" + std::to_string(i), "", true});
  items.push_back({"description.xml", "<GDTF/>"});
  ASSERT_TRUE(writeZip(dir / "many.gdtf", items));
  auto g = loadGdtf(dir / "many.gdtf");
  ASSERT_FALSE(g.ok());
  EXPECT_NE(g.error().message.find("entries, more than the limit of 20000"), std::string::npos) << g.error().str();
}

TEST(ZipArchive, RefusesUnsafeNames) {
  TempDir dir("names");
  for (const char* bad : {"../escape.txt", "wheels/../../etc/passwd", "/abs.txt", "C:/win.txt"}) {
    ASSERT_TRUE(writeZip(dir / "bad.zip", {{"description.xml", "<GDTF/>"}, {bad, "x"}})) << bad;
    auto zip = ZipArchive::open(dir / "bad.zip");
    ASSERT_FALSE(zip.ok()) << bad;
    EXPECT_EQ(zip.error().place, "entry 1") << bad;
    EXPECT_NE(zip.error().message.find("expected a relative path"), std::string::npos) << zip.error().str();
  }
}

// Patches the declared uncompressed size of the only entry in both headers: the reader must
// notice that the data is longer than declared and must not write past its buffer.
TEST(ZipArchive, RefusesAnEntryLongerThanDeclared) {
  TempDir dir("forged");
  ASSERT_TRUE(writeZip(dir / "f.zip", {{"a.txt", std::string(5000, 'q')}}));
  std::string bytes = test::readFile(dir / "f.zip");
  auto patch = [&](const char sig[4], std::size_t offset) {
    std::size_t at = bytes.find(std::string(sig, 4));
    ASSERT_NE(at, std::string::npos);
    const std::uint32_t small = 10;
    std::memcpy(&bytes[at + offset], &small, 4);  // zip is little-endian, as this machine
  };
  patch("PK\x03\x04", 22);  // local header: uncompressed size
  patch("PK\x01\x02", 24);  // central directory: uncompressed size
  test::writeFile(dir / "f.zip", bytes);
  auto zip = ZipArchive::open(dir / "f.zip");
  ASSERT_TRUE(zip.ok()) << zip.error().str();
  EXPECT_EQ(zip->entries()[0].sizeBytes, 10u);
  auto data = zip->read("a.txt");
  ASSERT_FALSE(data.ok());
  EXPECT_EQ(data.error().place, "entry 0");
}

}  // namespace
}  // namespace haze
