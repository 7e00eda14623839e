#include "renderer/gpu_venue.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "shaders/interface.h"

namespace haze {
namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  float u, v;
};
static_assert(sizeof(Vertex) == 32, "venue vertex layout is read by venue.vert.glsl");

// The vertex array's one buffer binding point (a C++-side slot, not a shader interface).
constexpr GLuint kVertexBufferBinding = 0;

}  // namespace

GpuVenue::GpuVenue(const Venue& venue) : boundsMin_(venue.boundsMin), boundsMax_(venue.boundsMax) {
  std::vector<Vertex> verts;
  std::vector<uint32_t> idx;
  for (const Primitive& p : venue.primitives) {
    Draw d{static_cast<GLsizei>(p.indices.size()), idx.size() * sizeof(uint32_t),
           static_cast<GLint>(verts.size()), p.material};
    for (size_t i = 0; i < p.positions.size(); ++i) {
      const glm::vec2 uv = p.uvs.empty() ? glm::vec2(0.0f) : p.uvs[i];
      verts.push_back({p.positions[i], p.normals[i], uv.x, uv.y});
    }
    idx.insert(idx.end(), p.indices.begin(), p.indices.end());
    draws_.push_back(d);
  }
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(verts.size() * sizeof(Vertex)), verts.data(), 0);
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(idx.size() * sizeof(uint32_t)), idx.data(), 0);
  glVertexArrayVertexBuffer(vao_.id(), kVertexBufferBinding, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  struct Attribute {
    GLuint location;
    GLint size;
    GLuint offset;
  };
  const Attribute attributes[] = {{HAZE_ATTR_POSITION, 3, offsetof(Vertex, position)},
                                  {HAZE_ATTR_NORMAL, 3, offsetof(Vertex, normal)},
                                  {HAZE_ATTR_UV, 2, offsetof(Vertex, u)}};
  for (const Attribute& a : attributes) {
    glEnableVertexArrayAttrib(vao_.id(), a.location);
    glVertexArrayAttribFormat(vao_.id(), a.location, a.size, GL_FLOAT, GL_FALSE, a.offset);
    glVertexArrayAttribBinding(vao_.id(), a.location, kVertexBufferBinding);
  }

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

void GpuVenue::draw(const Draw& d) const {
  glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(d.firstIndexBytes), d.baseVertex);
}

}  // namespace haze
