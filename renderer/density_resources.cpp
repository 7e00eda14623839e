#include "renderer/density_resources.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "shows/scene/camera_basis.h"
#include "shaders/interface.h"

namespace haze {
namespace {

uint64_t mix(uint64_t h, uint64_t v) { return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)); }
uint64_t mixf(uint64_t h, float f) { return mix(h, std::hash<float>{}(f)); }
uint64_t mixv(uint64_t h, const glm::vec3& v) { return mixf(mixf(mixf(h, v.x), v.y), v.z); }

// The eye map: texels across the screen (the other side by the aspect) and view-depth slices.
constexpr int kEyeTexelsAcross = 64;
constexpr int kEyeSlices = 128;

gl::Texture texture3D(const char* label, int w, int h, int d, const float* data) {
  gl::Texture t(GL_TEXTURE_3D, label);
  glTextureStorage3D(t.id(), 1, GL_R32F, w, h, d);
  glTextureSubImage3D(t.id(), 0, 0, 0, 0, w, h, d, GL_RED, GL_FLOAT, data);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
  return t;
}

// fn(k) for k in [0, n), over the machine's threads: each k writes texels of its own, so the
// maps are the same whatever the thread count.
void parallelFor(int n, const std::function<void(int)>& fn) {
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::max(n, 1));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int k = t; k < n; k += threads) fn(k);
    });
  for (int k = 0; k < n; k += threads) fn(k);
  for (std::thread& t : pool) t.join();
}

float farthestCornerM(const glm::vec3& from, const DensityField& f) {
  float d = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? f.maxM.x : f.minM.x, (i & 2) ? f.maxM.y : f.minM.y, (i & 4) ? f.maxM.z : f.minM.z);
    d = std::max(d, glm::length(c - from));
  }
  return d;
}

}  // namespace

void DensityResources::update(const FrameState& frame, float aspect, const BeamResources& beams) {
  const DensityField* field = frame.medium.density.get();
  on_ = field && !field->empty();
  if (!on_) {
    field_ = nullptr;
    keep_.reset();
    return;
  }
  if (field != field_) {
    density_ = texture3D("density", field->nx, field->ny, field->nz, field->values.data());
    field_ = field;
    keep_ = frame.medium.density;  // the pointer is the cache key: keep it alive
    min_ = field->minM;
    invSize_ = 1.0f / (field->maxM - field->minM);
    eyeKey_ = lensKey_ = 0;
  }
  const uint64_t fieldKey = std::hash<const void*>{}(field);

  // From the eye: slice k at view depth k * depth / (n - 1), each the last one's plus the
  // integral of D between them.
  const CameraState& cam = frame.camera;
  uint64_t ek = mix(fieldKey, 11);
  ek = mixv(mixv(mixv(ek, cam.position), cam.target), cam.up);
  ek = mixf(mixf(mixf(ek, cam.fovYDeg), cam.farM), aspect);
  if (ek != eyeKey_) {
    const CameraBasis b = cameraBasis(cam, aspect);
    eye_ = cam.position;
    forward_ = b.forward;
    rightTan_ = b.right * b.tanX;
    upTan_ = b.up * b.tanY;
    const float far = cam.farM > 0.0f ? cam.farM : 100.0f;
    pathDepth_ = std::clamp(farthestCornerM(eye_, *field) * 1.05f, 0.1f, far);
    const int nu = kEyeTexelsAcross;
    const int nv = std::clamp(static_cast<int>(std::lround(kEyeTexelsAcross / std::max(aspect, 1e-3f))), 8, 256);
    const int nz = kEyeSlices;
    scratch_.assign(static_cast<size_t>(nu) * nv * nz, 0.0f);
    const float dz = pathDepth_ / static_cast<float>(nz - 1);
    parallelFor(nv, [&](int j) {
      for (int i = 0; i < nu; ++i) {
        const glm::vec2 ndc((i + 0.5f) / nu * 2.0f - 1.0f, (j + 0.5f) / nv * 2.0f - 1.0f);
        const glm::vec3 v = forward_ + ndc.x * rightTan_ + ndc.y * upTan_;
        // Stored per metre of ray: the path over the ray's length, so that D = 1 gives the view
        // depth itself, which interpolates exactly; the shader multiplies by its own ray's length.
        const float perLength = 1.0f / glm::length(v);
        float path = 0.0f;
        for (int k = 1; k < nz; ++k) {
          path += field->integral(eye_ + v * (dz * (k - 1)), eye_ + v * (dz * k));
          scratch_[(static_cast<size_t>(k) * nv + j) * nu + i] = path * perLength;
        }
      }
    });
    eyePath_ = texture3D("density_eye_path", nu, nv, nz, scratch_.data());
    backgroundPath_ = field->integral(eye_, eye_ + forward_ * far);
    eyeKey_ = ek;
  }

  // From each lens: texel (a, b) of a beam's tile is the light-map direction at its centre,
  // slice k the distance k * reach / (n - 1).
  const int n = beams.count();
  uint64_t lk = mix(fieldKey, 13 + static_cast<uint64_t>(n));
  for (int i = 0; i < n; ++i) {
    const GpuBeam& g = beams.beams()[static_cast<size_t>(i)];
    lk = mix(mixf(mixv(mixv(lk, glm::vec3(g.lensPos)), glm::vec3(g.zb)), g.xb.w), std::hash<float>{}(g.lens.w));
    lk = mixv(lk, glm::vec3(g.xb));
  }
  if (lk != lensKey_ && n > 0) {
    side_ = n <= 64 ? 32 : 16;
    slices_ = n <= 64 ? 64 : 32;
    tiles_ = std::min(n, 64);
    tilesDown_ = (n + tiles_ - 1) / tiles_;
    const int w = tiles_ * side_, h = tilesDown_ * side_;
    scratch_.assign(static_cast<size_t>(w) * h * slices_, 0.0f);
    parallelFor(n, [&](int i) {
      if (!beams.drawn(i)) return;
      const GpuBeam& g = beams.beams()[static_cast<size_t>(i)];
      const glm::vec3 lens(g.lensPos), xb(g.xb), yb(g.yb), zb(g.zb);
      const float reach = 1.0f / std::max(g.lens.w, 1e-6f);
      const float dr = reach / static_cast<float>(slices_ - 1);
      const int x0 = (i % tiles_) * side_, y0 = (i / tiles_) * side_;
      for (int bj = 0; bj < side_; ++bj)
        for (int ai = 0; ai < side_; ++ai) {
          const glm::vec2 uv((ai + 0.5f) / side_ * 2.0f - 1.0f, (bj + 0.5f) / side_ * 2.0f - 1.0f);
          const glm::vec2 gate = uv / std::max(g.xb.w, 1e-6f);
          const glm::vec3 wdir = glm::normalize(gate.x * xb + gate.y * yb + zb);
          float path = 0.0f;
          for (int k = 1; k < slices_; ++k) {
            path += field->integral(lens + wdir * (dr * (k - 1)), lens + wdir * (dr * k));
            scratch_[(static_cast<size_t>(k) * h + y0 + bj) * w + x0 + ai] = path;
          }
        }
    });
    lensPath_ = texture3D("density_lens_path", w, h, slices_, scratch_.data());
    lensKey_ = lk;
  }
}

void DensityResources::bind(unsigned int prog) const {
  glProgramUniform1i(prog, HAZE_LOC_DENSITY_ON, on_ ? 1 : 0);
  if (!on_) return;
  glBindTextureUnit(HAZE_UNIT_DENSITY, density_.id());
  glBindTextureUnit(HAZE_UNIT_EYE_PATH, eyePath_.id());
  glBindTextureUnit(HAZE_UNIT_LENS_PATH, lensPath_.id());
  glProgramUniform3fv(prog, HAZE_LOC_DENSITY_MIN, 1, glm::value_ptr(min_));
  glProgramUniform3fv(prog, HAZE_LOC_DENSITY_INV_SIZE, 1, glm::value_ptr(invSize_));
  glProgramUniform3fv(prog, HAZE_LOC_EYE_PATH_EYE, 1, glm::value_ptr(eye_));
  glProgramUniform3fv(prog, HAZE_LOC_EYE_PATH_FORWARD, 1, glm::value_ptr(forward_));
  glProgramUniform3fv(prog, HAZE_LOC_EYE_PATH_RIGHT_TAN, 1, glm::value_ptr(rightTan_));
  glProgramUniform3fv(prog, HAZE_LOC_EYE_PATH_UP_TAN, 1, glm::value_ptr(upTan_));
  glProgramUniform1f(prog, HAZE_LOC_EYE_PATH_DEPTH, pathDepth_);
  glProgramUniform4i(prog, HAZE_LOC_LENS_PATH_GRID, tiles_, tilesDown_, side_, slices_);
}

}  // namespace haze
