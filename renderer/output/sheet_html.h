// The review sheet as one HTML file: the same SheetDoc as the PDF (renderer/output/sheet_pdf.h),
// for a browser or a tablet at the desk. One file, so it can be mailed or copied as the PDF is:
// the thumbnails are embedded as PNG data URIs (about 60-120 kB a 320x180 thumbnail). Every text
// of the show (title, cue labels, camera and fixture names) is user input and is escaped; the
// page holds no script.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "fixtures/core/result.h"
#include "renderer/output/sheet_pdf.h"

namespace haze {

// Text as HTML character data or a quoted attribute value: & < > " ' replaced by references.
std::string htmlEscape(std::string_view text);

// The whole page. Each cue is a <tr class="cue" data-cue="NUMBER"> holding one <img
// class="thumb"> per thumbnail; the patch is <table class="patch">.
std::string sheetHtml(const SheetDoc& doc);

// Writes sheetHtml(doc) atomically (a temporary file beside it, renamed when complete).
Status writeSheetHtml(const SheetDoc& doc, const std::filesystem::path& file);

}  // namespace haze
