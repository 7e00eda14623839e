// The GUI's window and its OpenGL 4.5 context, through GLFW.
#include "app/gui/window_context.h"

#include <string>

#include <GLFW/glfw3.h>

#include "renderer/gl/debug.h"

namespace haze {

namespace {

// GLFW's own words for its last error, so that a failure says which call failed and why (no
// display, a missing extension, no matching GLX config) rather than a guess.
std::string glfwReason() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  if (code == GLFW_NO_ERROR) return "no reason given";
  return description ? std::string(description) : "GLFW error " + std::to_string(code);
}

}  // namespace

Result<std::unique_ptr<WindowContext>> WindowContext::create(int width, int height, const std::string& title,
                                                             bool debug) {
  if (!glfwInit())
    return Error{"", "GLFW", "cannot open a window: " + glfwReason() + " (set DISPLAY, or use `haze render` headless)"};
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* w = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!w) {
    const std::string reason = glfwReason();
    glfwTerminate();
    return Error{"", "GLFW", "cannot create an OpenGL 4.5 core window: " + reason + " (Mesa 20 or newer provides one)"};
  }
  glfwMakeContextCurrent(w);
  glfwSwapInterval(1);
  if (debug) gl::enableDebugOutput();
  auto ctx = std::unique_ptr<WindowContext>(new WindowContext());
  ctx->window_ = w;
  return ctx;
}

WindowContext::~WindowContext() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::string WindowContext::description() const { return currentGlDescription() + ", GLFW window"; }

}  // namespace haze
