// cairo's PDF surface writes into memory; the bytes then replace the file atomically.
#include "renderer/output/sheet_pdf.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "fixtures/core/atomic_file.h"

namespace haze {
namespace {

using L = SheetLayout;

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

class Page {
 public:
  explicit Page(cairo_t* cr) : cr_(cr) {}

  void text(double x, double y, const std::string& s, double size, bool bold = false, double maxWidth = 0) {
    cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, size);
    std::string shown = s;
    // Too long for its column: shortened with a visible "..." rather than running into the next.
    if (maxWidth > 0 && width(shown) > maxWidth) {
      while (!shown.empty() && width(shown + "...") > maxWidth) {
        shown.pop_back();
        while (!shown.empty() && (static_cast<unsigned char>(shown.back()) & 0xC0) == 0x80) shown.pop_back();
      }
      shown += "...";
    }
    cairo_move_to(cr_, x, y);
    cairo_show_text(cr_, shown.c_str());
  }

  void image(const SheetImage& img, double x, double y, double w, double h) {
    if (img.width <= 0 || img.height <= 0 || img.rgb8.size() != static_cast<size_t>(img.width) * img.height * 3) return;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, img.width, img.height);
    const int stride = cairo_image_surface_get_stride(surface);
    unsigned char* dst = cairo_image_surface_get_data(surface);
    cairo_surface_flush(surface);
    for (int j = 0; j < img.height; ++j) {
      auto* row = reinterpret_cast<uint32_t*>(dst + static_cast<size_t>(j) * stride);
      for (int i = 0; i < img.width; ++i) {
        const unsigned char* p = &img.rgb8[(static_cast<size_t>(j) * img.width + i) * 3];
        row[i] = (uint32_t{p[0]} << 16) | (uint32_t{p[1]} << 8) | p[2];
      }
    }
    cairo_surface_mark_dirty(surface);
    cairo_save(cr_);
    cairo_translate(cr_, x, y);
    cairo_scale(cr_, w / img.width, h / img.height);
    cairo_set_source_surface(cr_, surface, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr_), CAIRO_FILTER_GOOD);
    cairo_paint(cr_);
    cairo_restore(cr_);
    cairo_surface_destroy(surface);
  }

  void line(double x0, double y0, double x1, double y1, double grey) {
    cairo_set_source_rgb(cr_, grey, grey, grey);
    cairo_set_line_width(cr_, 0.5);
    cairo_move_to(cr_, x0, y0);
    cairo_line_to(cr_, x1, y1);
    cairo_stroke(cr_);
    cairo_set_source_rgb(cr_, 0, 0, 0);
  }

  void header(const SheetDoc& doc, const std::string& what, int page) {
    cairo_set_source_rgb(cr_, 0, 0, 0);
    text(L::kMargin, L::kMargin + 10, doc.title, 14, true, 500);
    text(L::kMargin, L::kMargin + 26, doc.subtitle + "  -  " + what, 8, false, 600);
    text(L::kPageWidth - L::kMargin - 50, L::kMargin + 10, "page " + std::to_string(page), 8);
  }

 private:
  double width(const std::string& s) {
    cairo_text_extents_t e;
    cairo_text_extents(cr_, s.c_str(), &e);
    return e.x_advance;
  }
  cairo_t* cr_;
};

}  // namespace

Status writeSheetPdf(const SheetDoc& doc, const std::filesystem::path& file) {
  std::string bytes;
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(appendBytes, &bytes, L::kPageWidth, L::kPageHeight);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, doc.title.c_str());
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "haze sheet");
  cairo_t* cr = cairo_create(surface);
  Page page(cr);
  int pageNumber = 1;
  const double cameraColumns = static_cast<double>(std::max<size_t>(doc.cameras.size(), 1));
  const double changesX = L::thumbX(static_cast<int>(cameraColumns)) + 4;
  const double changesWidth = L::kPageWidth - L::kMargin - changesX;

  for (size_t i = 0; i < doc.cues.size(); ++i) {
    const int row = static_cast<int>(i);
    if (row % L::kRowsPerPage == 0) {
      if (row > 0) {
        cairo_show_page(cr);
        ++pageNumber;
      }
      page.header(doc, "cues", pageNumber);
      for (size_t c = 0; c < doc.cameras.size(); ++c)
        page.text(L::thumbX(static_cast<int>(c)), L::kFirstRowY - 6, doc.cameras[c], 8, true, L::kThumbWidth);
      page.text(changesX, L::kFirstRowY - 6, "changes", 8, true);
    }
    const SheetCue& cue = doc.cues[i];
    const double top = L::kFirstRowY + (row % L::kRowsPerPage) * L::kRowHeight;
    page.line(L::kMargin, top, L::kPageWidth - L::kMargin, top, 0.6);
    page.text(L::kMargin, top + 22, cue.number, 18, true, 130);
    page.text(L::kMargin, top + 38, cue.label, 9, false, L::kThumbX - L::kMargin - 8);
    page.text(L::kMargin, top + 52, cue.timing, 7, false, L::kThumbX - L::kMargin - 8);
    for (size_t c = 0; c < cue.thumbnails.size(); ++c)
      page.image(cue.thumbnails[c], L::thumbX(static_cast<int>(c)), L::thumbY(row), L::kThumbWidth, L::kThumbHeight);
    // Every change is listed: past kChangeLines the lines close up and the type shrinks to fit
    // the row, so the desk never reads "and more".
    const size_t lines = cue.changes.size();
    const double step = lines > static_cast<size_t>(L::kChangeLines) ? 11.0 * L::kChangeLines / static_cast<double>(lines) : 11.0;
    const double size = std::min(7.0, step * 0.8);
    for (size_t k = 0; k < lines; ++k)
      page.text(changesX, top + 14 + step * static_cast<double>(k), cue.changes[k], size, false, changesWidth);
    if (cue.changes.empty()) page.text(changesX, top + 14, "no change", 7, false, changesWidth);
  }

  // The patch, on pages of its own.
  const double columns[] = {L::kMargin, 300, 470, 640, 720};
  for (size_t i = 0; i < doc.patch.size() || i == 0; ++i) {
    if (i % L::kPatchRowsPerPage == 0) {
      if (i > 0 || !doc.cues.empty()) {
        cairo_show_page(cr);
        ++pageNumber;
      }
      page.header(doc, "patch", pageNumber);
      const char* heads[] = {"fixture", "profile", "mode", "universe", "address"};
      for (int c = 0; c < 5; ++c) page.text(columns[c], L::kFirstRowY - 6, heads[c], 8, true);
      if (doc.patch.empty()) page.text(L::kMargin, L::kFirstRowY + 10, "no fixtures", 8);
    }
    if (doc.patch.empty()) break;
    const SheetPatchRow& p = doc.patch[i];
    const double y = L::kFirstRowY + 10 + 11.5 * (i % L::kPatchRowsPerPage);
    const std::string cells[] = {p.fixture, p.profile, p.mode, p.universe, p.address};
    for (int c = 0; c < 5; ++c) page.text(columns[c], y, cells[c], 7.5, false, (c < 4 ? columns[c + 1] : 806) - columns[c] - 6);
  }
  cairo_show_page(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    return Error{file.string(), "", std::string("cannot make the PDF: ") + cairo_status_to_string(status)};
  return writeFileAtomically(file, bytes, false);
}

}  // namespace haze
