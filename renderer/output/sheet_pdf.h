// The review sheet as a PDF (cairo): one row per cue (number, label, timing, a thumbnail per
// camera, what changes), then the patch on a page of its own. The layout is fixed so that a
// test can find each thumbnail on the rendered page (docs/output.md, "Review sheet").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fixtures/core/result.h"

namespace haze {

struct SheetImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb8;  // sRGB, row 0 at the top
};

struct SheetCue {
  std::string number, label, timing;  // timing: "fade 5 s, delay 0 s, follow -"
  std::vector<SheetImage> thumbnails;  // one per camera, in SheetDoc::cameras' order
  std::vector<std::string> changes;    // "11-20 Alpha Spot @ 70 %, palette Blue, gobo Spokes"
};

struct SheetPatchRow {
  std::string fixture, profile, mode, universe, address;
};

struct SheetDoc {
  std::string title;                 // the show
  std::string subtitle;              // cue list, date, haze version
  std::vector<std::string> cameras;  // column headings of the thumbnails
  std::vector<SheetCue> cues;
  std::vector<SheetPatchRow> patch;
};

// The fixed layout, in PDF points (1/72 inch) on A4 landscape, y down from the top edge.
struct SheetLayout {
  static constexpr double kPageWidth = 842, kPageHeight = 595, kMargin = 36;
  static constexpr double kFirstRowY = 84, kRowHeight = 104;
  static constexpr double kThumbX = 176, kThumbWidth = 160, kThumbHeight = 90, kThumbGap = 8;
  static constexpr int kRowsPerPage = 4;
  static constexpr int kChangeLines = 8;  // at 7 pt; more are set closer and smaller to fit the row
  static constexpr int kPatchRowsPerPage = 40;
  // Top-left corner of cue row `row`'s thumbnail `camera` on its page (row % kRowsPerPage).
  static double thumbX(int camera) { return kThumbX + camera * (kThumbWidth + kThumbGap); }
  static double thumbY(int row) { return kFirstRowY + (row % kRowsPerPage) * kRowHeight + 4; }
};

// Writes the sheet atomically (a temporary file beside it, renamed when complete).
Status writeSheetPdf(const SheetDoc& doc, const std::filesystem::path& file);

}  // namespace haze
