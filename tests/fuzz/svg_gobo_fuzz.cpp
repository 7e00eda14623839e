// Fuzz harness: an SVG gobo's bytes through librsvg (goboFromSvgBytes, QLC+'s rule), then
// lookups over the gate as the light-map bake makes them.
#include <span>

#include "fixtures/gobo_image.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptSvgGobo(const uint8_t* data, size_t size) {
  auto g = goboFromSvgBytes(std::span<const uint8_t>(data, size), "fuzz", "fuzz.svg", GoboBackground::White);
  if (!g) return false;
  const GoboImage& img = **g;
  if (img.width < 1 || img.height < 1 || img.width > kSvgGoboPixels || img.height > kSvgGoboPixels) __builtin_trap();
  for (float s : {0.0f, 0.3f, 0.5f, 1.0f})
    for (float t : {0.0f, 0.7f, 1.0f}) {
      const float v = img.sample(s, t);
      if (!(v >= 0.0f && v <= 1.0f)) __builtin_trap();
    }
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptSvgGobo)
