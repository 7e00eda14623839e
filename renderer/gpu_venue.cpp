#include "renderer/gpu_venue.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "shaders/interface.h"

namespace haze {
namespace {

static_assert(sizeof(VenueVertex) == 32, "venue vertex layout is read by venue.vert.glsl");

// The vertex array's one buffer binding point (a C++-side slot, not a shader interface).
constexpr GLuint kVertexBufferBinding = 0;

}  // namespace

void setVenueVertexLayout(GLuint vao, GLuint buffer) {
  glVertexArrayVertexBuffer(vao, kVertexBufferBinding, buffer, 0, sizeof(VenueVertex));
  struct Attribute {
    GLuint location;
    GLint size;
    GLuint offset;
  };
  const Attribute attributes[] = {{HAZE_ATTR_POSITION, 3, offsetof(VenueVertex, position)},
                                  {HAZE_ATTR_NORMAL, 3, offsetof(VenueVertex, normal)},
                                  {HAZE_ATTR_UV, 2, offsetof(VenueVertex, u)}};
  for (const Attribute& a : attributes) {
    glEnableVertexArrayAttrib(vao, a.location);
    glVertexArrayAttribFormat(vao, a.location, a.size, GL_FLOAT, GL_FALSE, a.offset);
    glVertexArrayAttribBinding(vao, a.location, kVertexBufferBinding);
  }
}

GpuVenue::GpuVenue(const Venue& venue) : boundsMin_(venue.boundsMin), boundsMax_(venue.boundsMax) {
  std::vector<VenueVertex> verts;
  std::vector<uint32_t> idx;
  std::vector<std::vector<uint32_t>> byMaterial(std::max<size_t>(venue.materials.size(), 1));
  for (const Primitive& p : venue.primitives) {
    const uint32_t base = static_cast<uint32_t>(verts.size());
    for (size_t i = 0; i < p.positions.size(); ++i) {
      const glm::vec2 uv = p.uvs.empty() ? glm::vec2(0.0f) : p.uvs[i];
      verts.push_back({p.positions[i], p.normals[i], uv.x, uv.y});
    }
    const size_t m = p.material >= 0 && static_cast<size_t>(p.material) < venue.materials.size()
                         ? static_cast<size_t>(p.material)
                         : 0;  // the default material
    for (uint32_t i : p.indices) byMaterial[m].push_back(base + i);
  }
  for (size_t m = 0; m < byMaterial.size(); ++m) {
    if (byMaterial[m].empty()) continue;
    draws_.push_back({static_cast<GLsizei>(byMaterial[m].size()), idx.size() * sizeof(uint32_t), 0, static_cast<int>(m)});
    idx.insert(idx.end(), byMaterial[m].begin(), byMaterial[m].end());
  }
  indexCount_ = static_cast<GLsizei>(idx.size());
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(verts.size() * sizeof(VenueVertex)), verts.data(), 0);
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(idx.size() * sizeof(uint32_t)), idx.data(), 0);
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  setVenueVertexLayout(vao_.id(), vertices_.id());

  for (const Texture& t : venue.textures) {
    gl::Texture tex(GL_TEXTURE_2D, "venue_texture " + t.name);
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(t.width, t.height))));
    glTextureStorage2D(tex.id(), levels, t.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, t.width, t.height);
    glTextureSubImage2D(tex.id(), 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba8.data());
    glGenerateTextureMipmap(tex.id());
    glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    textures_.push_back(std::move(tex));
  }
  for (const Material& m : venue.materials)
    materials_.push_back({m.baseColor, m.emissive, m.baseColorTexture, m.emissiveTexture});
}

void GpuVenue::bind() const { glBindVertexArray(vao_.id()); }

void GpuVenue::drawAll() const {
  if (indexCount_ > 0) glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

void GpuVenue::draw(const Draw& d) const {
  glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(d.firstIndexBytes), d.baseVertex);
}

}  // namespace haze
