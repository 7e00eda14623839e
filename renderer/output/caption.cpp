#include "renderer/output/caption.h"

#include <cairo.h>

#include <algorithm>
#include <cstdint>

namespace haze {

CaptionBand captionBand(int width, int height) {
  const int bandHeight = std::max(10, height / 14);
  return {.x = 0, .y = height - bandHeight, .width = std::min(width, bandHeight * 16), .height = bandHeight};
}

void burnCaption(std::vector<unsigned char>& rgb8, int width, int height, const std::string& text) {
  if (width <= 0 || height <= 0 || rgb8.size() != static_cast<size_t>(width) * height * 3) return;
  const CaptionBand band = captionBand(width, height);
  // Only the band goes through cairo: copied out, drawn on, copied back.
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, band.width, band.height);
  const int stride = cairo_image_surface_get_stride(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  cairo_surface_flush(surface);
  for (int j = 0; j < band.height; ++j) {
    auto* row = reinterpret_cast<uint32_t*>(data + static_cast<size_t>(j) * stride);
    for (int i = 0; i < band.width; ++i) {
      const unsigned char* p = &rgb8[(static_cast<size_t>(band.y + j) * width + band.x + i) * 3];
      row[i] = (uint32_t{p[0]} << 16) | (uint32_t{p[1]} << 8) | p[2];
    }
  }
  cairo_surface_mark_dirty(surface);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgba(cr, 0, 0, 0, 0.6);
  cairo_paint(cr);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, band.height * 0.6);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, 0, 0, band.width, band.height);
  cairo_clip(cr);
  cairo_move_to(cr, band.height * 0.3, band.height * 0.75);
  cairo_show_text(cr, text.c_str());
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  for (int j = 0; j < band.height; ++j) {
    const auto* row = reinterpret_cast<const uint32_t*>(data + static_cast<size_t>(j) * stride);
    for (int i = 0; i < band.width; ++i) {
      unsigned char* p = &rgb8[(static_cast<size_t>(band.y + j) * width + band.x + i) * 3];
      p[0] = (row[i] >> 16) & 0xFF;
      p[1] = (row[i] >> 8) & 0xFF;
      p[2] = row[i] & 0xFF;
    }
  }
  cairo_surface_destroy(surface);
}

}  // namespace haze
