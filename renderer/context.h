// An OpenGL 4.5 core context, current on the calling thread. Two kinds: headless EGL (here, no
// window: Mesa's surfaceless platform, llvmpipe on any machine, or an EGL device on a GPU) and
// a GLFW window (app/window_context.*). The renderer only needs one to be current.
#pragma once

#include <memory>
#include <string>

#include "fixtures/core/result.h"

namespace haze {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits), EGL surfaceless"
  virtual std::string description() const = 0;
};

struct HeadlessOptions {
  bool debug = false;  // KHR_debug output with errors counted (tests) or printed
};

Result<std::unique_ptr<GlContext>> createHeadlessContext(const HeadlessOptions& options = {});

// The GL_RENDERER and GL_VERSION strings of the current context.
std::string currentGlDescription();

}  // namespace haze
