// Tiled light culling for the surface pass: a compute pass over the camera's depth that gives
// each 4x4-pixel tile a bit mask of the beams that can reach a surface seen in it
// (shaders/light_tiles.comp.glsl). With tens of beams most tiles see one to three of them.
#pragma once

#include "fixtures/core/result.h"
#include "renderer/gl/objects.h"
#include "shows/scene/frame_state.h"
#include "shaders/interface.h"

namespace haze {

class LightTiles {
 public:
  static constexpr int kTilePx = HAZE_TILE_PX;

  static Result<LightTiles> create(int width, int height);
  // For a new target size; the program is kept.
  void resize(int width, int height);

  // Fills the masks from the scene depth texture, for `beamCount` beams of the beams buffer
  // (which must be bound at its binding, with the scene depth at camera.glsl's unit).
  void update(const CameraState& camera, int beamCount);
  // The masks' buffer at its shaders/interface.h binding, for the surface pass.
  void bind() const;
  // Of the last update: the beams a tile's pixels try, on average over the tiles that see a
  // surface (reads the masks back, so for the bench only).
  double meanBeamsPerTile() const;
  int columns() const { return columns_; }
  int maskWords() const { return maskWords_; }

 private:
  gl::Program program_;
  gl::Buffer masks_;
  int width_ = 0, height_ = 0, columns_ = 0, rows_ = 0, maskWords_ = 0, capacityWords_ = 0;
};

}  // namespace haze
