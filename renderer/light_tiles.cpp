#include "renderer/light_tiles.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "renderer/camera_uniforms.h"
#include "renderer/gl/program.h"

namespace haze {

Result<LightTiles> LightTiles::create(int width, int height) {
  LightTiles t;
  auto program = gl::buildProgram({.label = "light_tiles", .compute = "light_tiles.comp.glsl"});
  if (!program) return program.error();
  t.program_ = std::move(*program);
  t.resize(width, height);
  return t;
}

void LightTiles::resize(int width, int height) {
  width_ = width;
  height_ = height;
  columns_ = (width + kTilePx - 1) / kTilePx;
  rows_ = (height + kTilePx - 1) / kTilePx;
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
  glProgramUniform2i(prog, HAZE_LOC_TILES_TARGET_SIZE, width_, height_);
  glProgramUniform1i(prog, HAZE_LOC_TILES_BEAM_COUNT, beamCount);
  glProgramUniform1i(prog, HAZE_LOC_TILES_MASK_WORDS, maskWords_);
  glProgramUniform2i(prog, HAZE_LOC_TILES_GRID, columns_, rows_);
  bind();
  glDispatchCompute(static_cast<GLuint>((columns_ + HAZE_TILE_GROUP_X - 1) / HAZE_TILE_GROUP_X),
                    static_cast<GLuint>(rows_), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

double LightTiles::meanBeamsPerTile() const {
  const int tiles = columns_ * rows_;
  if (!masks_ || tiles == 0) return 0.0;
  std::vector<uint32_t> words(static_cast<size_t>(tiles) * maskWords_);
  glGetNamedBufferSubData(masks_.id(), 0, static_cast<GLsizeiptr>(words.size() * 4), words.data());
  uint64_t bits = 0;
  int lit = 0;
  for (int t = 0; t < tiles; ++t) {
    int n = 0;
    for (int w = 0; w < maskWords_; ++w) n += std::popcount(words[static_cast<size_t>(t) * maskWords_ + w]);
    bits += static_cast<uint64_t>(n);
    lit += n > 0;
  }
  return lit > 0 ? static_cast<double>(bits) / lit : 0.0;
}

void LightTiles::bind() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, HAZE_SSBO_TILE_MASKS, masks_.id()); }

}  // namespace haze
