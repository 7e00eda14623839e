#include "renderer/gl/debug.h"

#include <atomic>
#include <cstdio>
#include <mutex>

#include "renderer/gl/gl.h"

namespace haze::gl {
namespace {

std::atomic<int> g_errors{0};
std::mutex g_mutex;
std::string g_last;
bool g_print = true;

void APIENTRY onMessage(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei length,
                          const GLchar* message, const void*) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  // Compile errors come back from gl::buildProgram, with the file and line they are in; the
  // driver's copy here would name lines of the assembled source.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  ++g_errors;
  std::lock_guard lock(g_mutex);
  g_last.assign(message, length > 0 ? static_cast<size_t>(length) : std::char_traits<char>::length(message));
  if (g_print && g_errors <= 10) std::fprintf(stderr, "GL error: %s\n", g_last.c_str());
}

}  // namespace

void enableDebugOutput(bool printErrors) {
  g_print = printErrors;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onMessage, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

int debugErrorCount() { return g_errors; }

std::string lastDebugError() {
  std::lock_guard lock(g_mutex);
  return g_last;
}

void resetDebugErrors() {
  g_errors = 0;
  std::lock_guard lock(g_mutex);
  g_last.clear();
}

}  // namespace haze::gl
