// A caption burnt into a display frame (videos and PNG sequences, `--caption`): white text on a
// dark band in the bottom-left corner, sized to the frame (cairo). Never on radiometric images.
#pragma once

#include <string>
#include <vector>

namespace haze {

// rgb8: width x height x 3 sRGB bytes, row 0 at the top; changed in place. Only the band
// (captionBand) is touched.
void burnCaption(std::vector<unsigned char>& rgb8, int width, int height, const std::string& text);

struct CaptionBand {
  int x = 0, y = 0, width = 0, height = 0;
};
// The rectangle burnCaption may change (at most), for tests and for layouts around it.
CaptionBand captionBand(int width, int height);

}  // namespace haze
