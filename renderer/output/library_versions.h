// The versions of the output libraries this haze runs with (`haze --version`).
#pragma once

#include <string>

namespace haze {

// "OpenEXR 3.1.5, libavcodec 59.37.100, libavformat 59.27.100, cairo 1.16.0"
std::string outputLibraryVersions();

}  // namespace haze
