// The HTML review sheet without a browser (tests/cli/sheet_html.sh loads it in Chromium): show
// text cannot open a tag or leave an attribute, each thumbnail is one <img> whose data URI holds
// a PNG of the thumbnail's size, and nothing of a failed write is left under the name.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <regex>

#include "renderer/output/sheet_html.h"

namespace haze {
namespace {

std::string unbase64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned v = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const size_t d = digits.find(c);
    if (d == std::string::npos) return "not base64";
    v = (v << 6) | static_cast<unsigned>(d);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((v >> bits) & 0xFF);
    }
  }
  return out;
}

uint32_t bigEndian(const std::string& b, size_t at) {
  return (uint32_t{static_cast<unsigned char>(b[at])} << 24) | (uint32_t{static_cast<unsigned char>(b[at + 1])} << 16) |
         (uint32_t{static_cast<unsigned char>(b[at + 2])} << 8) | static_cast<unsigned char>(b[at + 3]);
}

SheetDoc hostileDoc() {
  const std::string evil = "<img src=x onerror=alert(1)>\"'&amp;</td></script>";
  SheetDoc doc{.title = "show " + evil, .subtitle = "cue list " + evil, .cameras = {"FOH " + evil, "Side"}};
  for (int i = 0; i < 3; ++i) {
    SheetCue cue{.number = std::to_string(i + 1) + evil, .label = evil, .timing = "fade 1 s"};
    for (int c = 0; c < 2; ++c) {
      // 5x3 pixels: odd sizes give a base64 tail with padding.
      SheetImage img{.width = 5 + c, .height = 3, .rgb8 = std::vector<unsigned char>(static_cast<size_t>(5 + c) * 3 * 3)};
      for (size_t k = 0; k < img.rgb8.size(); ++k) img.rgb8[k] = static_cast<unsigned char>(k * 37 + i);
      cue.thumbnails.push_back(img);
    }
    cue.changes = {"101 Spot " + evil};
    doc.cues.push_back(cue);
  }
  doc.patch.push_back({.fixture = "101 " + evil, .profile = evil, .mode = "-", .universe = "1", .address = "1"});
  return doc;
}

TEST(SheetHtml, EscapesEveryCharacterThatEndsTextOrAnAttribute) {
  EXPECT_EQ(htmlEscape("<a href=\"x\">'&'</a>"), "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(htmlEscape("Warm white 70 %"), "Warm white 70 %");
  EXPECT_EQ(htmlEscape("Bühne"), "Bühne");  // UTF-8 passes through
}

TEST(SheetHtml, ShowTextNeverBecomesMarkup) {
  const std::string html = sheetHtml(hostileDoc());
  // Tags the writer opens: 6 thumbnails are the only <img, and no <script at all.
  size_t images = 0;
  for (size_t at = html.find("<img"); at != std::string::npos; at = html.find("<img", at + 1)) ++images;
  EXPECT_EQ(images, 6u);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("onerror"), html.find("onerror=alert(1)&gt;"));  // only as text
  EXPECT_NE(html.find("&lt;img src=x onerror=alert(1)&gt;&quot;&#39;&amp;amp;&lt;/td&gt;&lt;/script&gt;"), std::string::npos);
}

TEST(SheetHtml, EachThumbnailIsAPngOfItsSize) {
  const SheetDoc doc = hostileDoc();
  const std::string html = sheetHtml(doc);
  const std::regex img(R"re(<img class="thumb" width="(\d+)" height="(\d+)" alt="[^"<>]*" src="data:image/png;base64,([A-Za-z0-9+/=]+)">)re");
  int n = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it, ++n) {
    const std::string png = unbase64((*it)[3].str());
    ASSERT_GT(png.size(), 24u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png.substr(12, 4), "IHDR");
    EXPECT_EQ(bigEndian(png, 16), static_cast<uint32_t>(doc.cues[n / 2].thumbnails[n % 2].width));
    EXPECT_EQ(bigEndian(png, 20), 3u);
    EXPECT_EQ((*it)[1].str(), std::to_string(5 + n % 2));
  }
  EXPECT_EQ(n, 6);
}

TEST(SheetHtml, AnUnwritablePathLeavesNothing) {
  const auto dir = std::filesystem::temp_directory_path() / ("haze-sheet-html-test-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "not-a-folder") << "x";
  const Status s = writeSheetHtml(hostileDoc(), dir / "not-a-folder" / "sheet.html");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().str().find("not-a-folder/sheet.html"), std::string::npos) << s.error().str();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace haze
