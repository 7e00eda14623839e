// The windowed GlContext: a GLFW window with an OpenGL 4.5 core context (GLX under X11, so
// Xvfb with Mesa works in tests). Only app/ knows GLFW; the renderer sees a current context.
#pragma once

#include <memory>
#include <string>

#include "fixtures/core/result.h"
#include "renderer/context.h"

struct GLFWwindow;

namespace haze {

class WindowContext final : public GlContext {
 public:
  static Result<std::unique_ptr<WindowContext>> create(int width, int height, const std::string& title,
                                                       bool debug);
  ~WindowContext() override;
  std::string description() const override;
  GLFWwindow* window() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace haze
