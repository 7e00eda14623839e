// Scoped GL state: each pass of a frame runs inside a PassScope (a KHR_debug group, so a GL
// debugger shows the frame as its passes, and the pass's timer query when timing is on) and sets
// the capabilities it needs with Capability guards, which put back what they found. A pass then
// neither depends on nor leaks the state of the pass before it.
#pragma once

#include <string_view>

#include "renderer/gl/gl.h"

namespace haze::gl {

class PassScope {
 public:
  // timer: a GL_TIME_ELAPSED query to run over the scope, or 0 for none.
  PassScope(std::string_view name, GLuint timer = 0) : timer_(timer) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.data());
    if (timer_) glBeginQuery(GL_TIME_ELAPSED, timer_);
  }
  ~PassScope() {
    if (timer_) glEndQuery(GL_TIME_ELAPSED);
    glPopDebugGroup();
  }
  PassScope(const PassScope&) = delete;
  PassScope& operator=(const PassScope&) = delete;

 private:
  GLuint timer_;
};

// glEnable or glDisable for a scope; the capability's earlier value comes back at its end.
class Capability {
 public:
  Capability(GLenum cap, bool on) : cap_(cap), was_(glIsEnabled(cap) == GL_TRUE) { set(on); }
  ~Capability() { set(was_); }
  Capability(const Capability&) = delete;
  Capability& operator=(const Capability&) = delete;

 private:
  void set(bool on) const { on ? glEnable(cap_) : glDisable(cap_); }
  GLenum cap_;
  bool was_;
};

// glDepthMask for a scope.
class DepthMask {
 public:
  explicit DepthMask(bool write) {
    glGetBooleanv(GL_DEPTH_WRITEMASK, &was_);
    glDepthMask(write ? GL_TRUE : GL_FALSE);
  }
  ~DepthMask() { glDepthMask(was_); }
  DepthMask(const DepthMask&) = delete;
  DepthMask& operator=(const DepthMask&) = delete;

 private:
  GLboolean was_ = GL_TRUE;
};

}  // namespace haze::gl
