#include "renderer/output/library_versions.h"

#include <OpenEXR/OpenEXRConfig.h>
#include <cairo.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

namespace haze {

std::string outputLibraryVersions() {
  // FFmpeg's and cairo's are asked at run time (the shared libraries loaded); OpenEXR's is the
  // one compiled against.
  const auto av = [](unsigned n) {
    return std::to_string(AV_VERSION_MAJOR(n)) + "." + std::to_string(AV_VERSION_MINOR(n)) + "." +
           std::to_string(AV_VERSION_MICRO(n));
  };
  return std::string("OpenEXR ") + OPENEXR_VERSION_STRING + ", libavcodec " + av(avcodec_version()) +
         ", libavformat " + av(avformat_version()) + ", cairo " + cairo_version_string();
}

}  // namespace haze
