// sheetHtml (see sheet_html.h): hand-written HTML, escaped at the one place text enters it.
#include "renderer/output/sheet_html.h"

#include "fixtures/core/atomic_file.h"
#include "shows/scene/image.h"

namespace haze {
namespace {

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += {kDigits[v >> 18], kDigits[(v >> 12) & 63], kDigits[(v >> 6) & 63], kDigits[v & 63]};
  }
  if (const size_t rest = bytes.size() - i; rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += {kDigits[v >> 18], kDigits[(v >> 12) & 63], rest == 2 ? kDigits[(v >> 6) & 63] : '=', '='};
  }
  return out;
}

// Print: a cue row never splits across pages, and the thumbnails print at the PDF's 160x90 pt.
constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", sans-serif; font-size: 10pt; margin: 1.5em; color: #000; }
h1 { font-size: 16pt; margin: 0; }
.subtitle { color: #444; margin: 0.2em 0 1em; }
table { border-collapse: collapse; }
th { text-align: left; font-size: 8pt; padding: 2px 8px 2px 0; border-bottom: 1px solid #999; }
td { vertical-align: top; padding: 4px 8px 4px 0; border-top: 1px solid #ccc; }
tr.cue { break-inside: avoid; }
.number { font-size: 18pt; font-weight: bold; }
.timing { font-size: 7pt; color: #444; }
img.thumb { width: 160pt; height: 90pt; display: block; background: #000; }
ul.changes { margin: 0; padding: 0; list-style: none; font-size: 8pt; }
table.patch td { font-size: 8pt; padding: 1px 12px 1px 0; }
h2 { font-size: 12pt; margin-top: 1.5em; break-before: page; }
)";

}  // namespace

std::string htmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string sheetHtml(const SheetDoc& doc) {
  const auto e = [](std::string_view s) { return htmlEscape(s); };
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += "<meta name=\"generator\" content=\"haze sheet\">\n";
  h += "<title>" + e(doc.title) + " - review sheet</title>\n<style>" + std::string(kStyle) + "</style>\n</head>\n<body>\n";
  h += "<h1>" + e(doc.title) + "</h1>\n<p class=\"subtitle\">" + e(doc.subtitle) + "</p>\n";

  h += "<table class=\"cues\">\n<thead><tr><th>cue</th>";
  for (const std::string& camera : doc.cameras) h += "<th>" + e(camera) + "</th>";
  h += "<th>changes</th></tr></thead>\n<tbody>\n";
  for (const SheetCue& cue : doc.cues) {
    h += "<tr class=\"cue\" data-cue=\"" + e(cue.number) + "\"><td><div class=\"number\">" + e(cue.number) +
         "</div><div class=\"label\">" + e(cue.label) + "</div><div class=\"timing\">" + e(cue.timing) + "</div></td>";
    for (size_t c = 0; c < cue.thumbnails.size(); ++c) {
      const SheetImage& img = cue.thumbnails[c];
      const std::string png = encodePng8(img.rgb8, img.width, img.height);
      const std::string camera = c < doc.cameras.size() ? doc.cameras[c] : "";
      // An image that cannot be encoded is a bug upstream (a buffer of the wrong size); the cell
      // says so rather than holding a broken image.
      if (png.empty()) {
        h += "<td>no thumbnail</td>";
        continue;
      }
      h += "<td><img class=\"thumb\" width=\"" + std::to_string(img.width) + "\" height=\"" + std::to_string(img.height) +
           "\" alt=\"cue " + e(cue.number) + ", " + e(camera) + "\" src=\"data:image/png;base64," + base64(png) + "\"></td>";
    }
    h += "<td>";
    if (cue.changes.empty()) {
      h += "no change";
    } else {
      h += "<ul class=\"changes\">";
      for (const std::string& line : cue.changes) h += "<li>" + e(line) + "</li>";
      h += "</ul>";
    }
    h += "</td></tr>\n";
  }
  h += "</tbody>\n</table>\n";

  h += "<h2>" + e(doc.title) + " - patch</h2>\n<table class=\"patch\">\n"
       "<thead><tr><th>fixture</th><th>profile</th><th>mode</th><th>universe</th><th>address</th></tr></thead>\n<tbody>\n";
  for (const SheetPatchRow& p : doc.patch)
    h += "<tr><td>" + e(p.fixture) + "</td><td>" + e(p.profile) + "</td><td>" + e(p.mode) + "</td><td>" + e(p.universe) +
         "</td><td>" + e(p.address) + "</td></tr>\n";
  if (doc.patch.empty()) h += "<tr><td colspan=\"5\">no fixtures</td></tr>\n";
  h += "</tbody>\n</table>\n</body>\n</html>\n";
  return h;
}

Status writeSheetHtml(const SheetDoc& doc, const std::filesystem::path& file) {
  return writeFileAtomically(file, sheetHtml(doc), false);
}

}  // namespace haze
