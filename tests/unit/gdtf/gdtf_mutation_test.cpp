// Hostile input without a crash: a real GDTF's description.xml and the archive bytes themselves,
// mutated deterministically. Each import must return (a profile or a one-line error naming the
// file); under ASan and UBSan any out-of-bounds read or overflow fails the run.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "fixtures/gdtf.h"
#include "fixtures/core/zip_archive.h"
#include "unit/gdtf/zip_builder.h"
#include "test_data.h"

namespace haze {
namespace {

const std::filesystem::path kLedPar = test::dataFile("gdtf/BlenderDMX@LED_PAR_64_RGBW@v0.3.gdtf");

struct Lcg {
  std::uint32_t x;
  std::uint32_t next(std::uint32_t n) {
    x = x * 1664525u + 1013904223u;
    return (x >> 8) % n;
  }
};

void expectCleanError(const Result<GdtfImport>& g, const std::string& file) {
  if (g.ok()) {
    EXPECT_TRUE(g->profile);
    return;
  }
  EXPECT_EQ(g.error().file.substr(0, file.size()), file);
  EXPECT_FALSE(g.error().message.empty());
  EXPECT_EQ(g.error().str().find('\n'), std::string::npos) << g.error().str();
}

std::string ledParXml() {
  auto zip = ZipArchive::open(kLedPar);
  EXPECT_TRUE(zip.ok());
  auto xml = zip->read("description.xml");
  EXPECT_TRUE(xml.ok());
  return std::string(xml->begin(), xml->end());
}

TEST(GdtfMutation, MutatedDescriptionNeverCrashes) {
  const std::string xml = ledParXml();
  ASSERT_GT(xml.size(), 1000u);
  test::TempDir dir("mutxml");
  const std::string path = (dir / "m.gdtf").string();
  Lcg rng{7};
  const char* tokens[] = {"\"", "<", ">", "/>", "nan", "-1e38", "1e38", "{", "}", ",", "None", "0/9", "65535/2", "-"};
  int refused = 0;
  for (int round = 0; round < 150; ++round) {
    std::string m = xml;
    const int edits = 1 + static_cast<int>(rng.next(4));
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng.next(static_cast<std::uint32_t>(m.size()));
      switch (rng.next(3)) {
        case 0: m[at] = static_cast<char>(rng.next(256)); break;
        case 1: m.insert(at, tokens[rng.next(sizeof tokens / sizeof *tokens)]); break;
        default: m.erase(at, rng.next(40)); break;
      }
    }
    ASSERT_TRUE(test::writeZip(dir / "m.gdtf", {{"description.xml", m}}));
    auto g = loadGdtf(dir / "m.gdtf");
    refused += !g.ok();
    expectCleanError(g, path);
  }
  EXPECT_GT(refused, 10);  // most edits break the XML or a number
}

TEST(GdtfMutation, CorruptArchiveBytesNeverCrash) {
  const std::string bytes = test::readFile(kLedPar);
  ASSERT_GT(bytes.size(), 1000u);
  Lcg rng{11};
  int refused = 0;
  for (int round = 0; round < 150; ++round) {
    std::string m = bytes;
    if (round % 5 == 0) {
      m.resize(rng.next(static_cast<std::uint32_t>(m.size())));  // truncated download
    } else {
      // Hit the headers at the end (central directory) as often as the data.
      for (int e = 0; e < 8; ++e) {
        const std::size_t at = rng.next(2) ? m.size() - 1 - rng.next(400) : rng.next(static_cast<std::uint32_t>(m.size()));
        m[at] = static_cast<char>(rng.next(256));
      }
    }
    auto g = loadGdtfFromMemory(std::vector<std::uint8_t>(m.begin(), m.end()), "corrupt.gdtf");
    refused += !g.ok();
    expectCleanError(g, "corrupt.gdtf");
  }
  EXPECT_GT(refused, 10);
}

}  // namespace
}  // namespace haze
