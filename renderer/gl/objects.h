// One move-only owner per kind of GL object, created with DSA (glCreate*) and labelled, so a
// debugger shows "shadow_map 3" instead of "Texture 37". No raw GL names leave renderer/gl/
// except through id() for the calls that need them.
#pragma once

#include <string_view>
#include <utility>

#include "renderer/gl/gl.h"

namespace haze::gl {

// Deleter policy per object kind; Object<Kind> owns one name of that kind.
template <class Kind>
class Object {
 public:
  Object() = default;  // empty: owns nothing (like a moved-from object)
  explicit Object(std::string_view label) {
    id_ = Kind::create();
    if (!label.empty())
      glObjectLabel(Kind::kLabelType, id_, static_cast<GLsizei>(label.size()), label.data());
  }
  ~Object() { reset(); }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Object& operator=(Object&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Kind::destroy(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct BufferKind {
  static constexpr GLenum kLabelType = GL_BUFFER;
  static GLuint create() { GLuint id; glCreateBuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayKind {
  static constexpr GLenum kLabelType = GL_VERTEX_ARRAY;
  static GLuint create() { GLuint id; glCreateVertexArrays(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct FramebufferKind {
  static constexpr GLenum kLabelType = GL_FRAMEBUFFER;
  static GLuint create() { GLuint id; glCreateFramebuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct SamplerKind {
  static constexpr GLenum kLabelType = GL_SAMPLER;
  static GLuint create() { GLuint id; glCreateSamplers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct ProgramKind {
  static constexpr GLenum kLabelType = GL_PROGRAM;
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct QueryKind {
  static constexpr GLenum kLabelType = GL_QUERY;
  static GLuint create() { GLuint id; glCreateQueries(GL_TIME_ELAPSED, 1, &id); return id; }
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

struct SamplesQueryKind {
  static constexpr GLenum kLabelType = GL_QUERY;
  static GLuint create() { GLuint id; glCreateQueries(GL_SAMPLES_PASSED, 1, &id); return id; }
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

struct RenderbufferKind {
  static constexpr GLenum kLabelType = GL_RENDERBUFFER;
  static GLuint create() { GLuint id; glCreateRenderbuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};

using Buffer = Object<BufferKind>;
using Renderbuffer = Object<RenderbufferKind>;
using VertexArray = Object<VertexArrayKind>;
using Framebuffer = Object<FramebufferKind>;
using Sampler = Object<SamplerKind>;
using Program = Object<ProgramKind>;
using TimerQuery = Object<QueryKind>;
using SamplesQuery = Object<SamplesQueryKind>;

// Textures need their target at creation, so they carry it.
class Texture {
 public:
  Texture() = default;
  Texture(GLenum target, std::string_view label) : target_(target) {
    glCreateTextures(target, 1, &id_);
    if (!label.empty())
      glObjectLabel(GL_TEXTURE, id_, static_cast<GLsizei>(label.size()), label.data());
  }
  ~Texture() { reset(); }
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  Texture(Texture&& o) noexcept : id_(std::exchange(o.id_, 0)), target_(o.target_) {}
  Texture& operator=(Texture&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
      target_ = o.target_;
    }
    return *this;
  }
  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) glDeleteTextures(1, &id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
  GLenum target_ = GL_TEXTURE_2D;
};

}  // namespace haze::gl
