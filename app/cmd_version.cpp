// `haze --version`: the release (CMake's project version), the commit it was configured from
// (git describe at configure time; "unknown" outside a git checkout), and the OpenGL context
// this machine gives the renderer, and the versions of the output libraries (EXR, video, PDF). No context is not an error here: the line says why.
#include <cstdio>
#include <string>

#include "app/commands.h"
#include "renderer/context.h"
#include "renderer/output/library_versions.h"

#ifndef HAZE_VERSION
#define HAZE_VERSION "unknown"
#endif
#ifndef HAZE_GIT_DESCRIBE
#define HAZE_GIT_DESCRIBE "unknown"
#endif

namespace haze {

int runVersion(const Args& args) {
  if (!args.empty()) {
    std::fprintf(stderr, "haze --version: takes no arguments (got '%s')\n", args.front().c_str());
    return kExitUsage;
  }
  std::printf("haze %s (git %s)\n", HAZE_VERSION, HAZE_GIT_DESCRIBE);
  auto context = createHeadlessContext();
  if (context)
    std::printf("renderer: %s\n", (*context)->description().c_str());
  else
    std::printf("renderer: no OpenGL context: %s\n", context.error().str().c_str());
  std::printf("output: %s\n", outputLibraryVersions().c_str());
  return 0;
}

}  // namespace haze
