#include "renderer/light_tiles.h"

#include <algorithm>

#include "renderer/camera_uniforms.h"
#include "renderer/gl/program.h"

namespace haze {

Result<LightTiles> LightTiles::create(int width, int height) {
  LightTiles t;
  auto program = gl::buildProgram({.label = "light_tiles", .compute = "light_tiles.comp.glsl"});
  if (!program) return program.error();
  t.program_ = std::move(*program);
  t.width_ = width;
  t.height_ = height;
  t.columns_ = (width + kTilePx - 1) / kTilePx;
  t.rows_ = (height + kTilePx - 1) / kTilePx;
  return t;
}

void LightTiles::update(const CameraState& camera, int beamCount) {
  maskWords_ = std::max(1, (beamCount + 31) / 32);
  const int words = maskWords_ * columns_ * rows_;
  if (words > capacityWords_) {
    capacityWords_ = words;
    masks_ = gl::Buffer("light_tile_masks");
    glNamedBufferStorage(masks_.id(), static_cast<GLsizeiptr>(words) * 4, nullptr, 0);
  }
  const GLuint prog = program_.id();
  glUseProgram(prog);
  setCameraUniforms(prog, camera, static_cast<float>(width_) / static_cast<float>(height_));
  glProgramUniform2i(prog, 0, width_, height_);
  glProgramUniform1i(prog, 1, beamCount);
  glProgramUniform1i(prog, 2, maskWords_);
  glProgramUniform2i(prog, 3, columns_, rows_);
  bind(3);
  glDispatchCompute(static_cast<GLuint>((columns_ + 7) / 8), static_cast<GLuint>(rows_), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void LightTiles::bind(GLuint binding) const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, masks_.id()); }

}  // namespace haze
