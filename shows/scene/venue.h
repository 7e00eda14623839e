// Venue: the stage's geometry as CPU data, flattened to world space from a glTF 2.0 file (node
// transforms applied, one Primitive per glTF primitive). The GPU renderer uploads it; the CPU
// reference traces it. No GL here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "fixtures/core/result.h"

namespace haze {

// An RGBA8 image as stored; colour textures are sRGB-encoded and decoded at lookup.
struct Texture {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgba8;  // width * height * 4, row 0 = glTF's uv v = 0 (top)
  bool srgb = true;
  // Bilinear, wrapping (glTF's default REPEAT), decoded to linear when srgb.
  glm::vec4 sampleLinear(glm::vec2 uv) const;
};

struct Material {
  std::string name;
  glm::vec4 baseColor{1.0f};     // linear RGBA factor (glTF baseColorFactor)
  int baseColorTexture = -1;     // index into Venue::textures, -1 none
  glm::vec3 emissive{0.0f};      // linear, cd/m^2 (emissiveFactor * KHR_materials_emissive_strength)
  int emissiveTexture = -1;
};

struct Primitive {
  std::string name;
  std::vector<glm::vec3> positions;  // world metres
  std::vector<glm::vec3> normals;    // world, unit (computed flat when the file has none)
  std::vector<glm::vec2> uvs;        // empty when the file has none
  std::vector<uint32_t> indices;     // triangles
  int material = 0;                  // index into Venue::materials (0 = the default material)
};

struct Venue {
  std::filesystem::path file;
  std::vector<Primitive> primitives;
  std::vector<Material> materials;   // [0] is the default (white, no texture)
  std::vector<Texture> textures;
  glm::vec3 boundsMin{0.0f};
  glm::vec3 boundsMax{0.0f};

  size_t triangleCount() const;
  // Albedo (linear RGB) of a primitive's material at a texture coordinate.
  glm::vec3 albedo(const Primitive& p, glm::vec2 uv) const;
  glm::vec3 emission(const Primitive& p, glm::vec2 uv) const;
};

// A venue of bare triangles (3 corners each, metres; a trailing partial triangle is dropped):
// one primitive of the default material, for ray casts over geometry that is no glTF yet.
Venue venueFromTriangles(std::vector<glm::vec3> trianglesM);

// What one venue may hold, checked before anything is allocated: a glTF file names counts of
// its own (and can instance one mesh from many nodes), so without these a few hundred bytes
// could ask for terabytes. Vertices are counted as read, and again when flat normals split
// them (3 per triangle) for a mesh without normals.
// The largest real venue in the tests has under 1 M triangles.
inline constexpr std::size_t kMaxVenueVertices = 32'000'000;
inline constexpr std::size_t kMaxVenueTriangles = 16'000'000;
inline constexpr std::size_t kMaxVenueNodeVisits = 1'000'000;  // node instances walked
inline constexpr std::size_t kMaxVenueTexturePixels = 8192u * 8192u;  // per image

struct VenueLimits {
  std::size_t maxVertices = kMaxVenueVertices;
  std::size_t maxTriangles = kMaxVenueTriangles;
  std::size_t maxNodeVisits = kMaxVenueNodeVisits;
};

// .gltf (with its .bin and images) or .glb. Errors name the file and what is wrong; no
// exception leaves it.
Result<Venue> loadVenue(const std::filesystem::path& file, const VenueLimits& limits = {});
// The bytes of a .glb (they start with "glTF") or of a .gltf. External URIs resolve against
// baseDir; with an empty baseDir only embedded data (data: URIs, the GLB chunk) is read and
// any file reference is an error. Errors name sourceName.
Result<Venue> loadVenueFromMemory(std::span<const std::uint8_t> bytes, const std::string& sourceName,
                                  const std::filesystem::path& baseDir = {}, const VenueLimits& limits = {});

}  // namespace haze
