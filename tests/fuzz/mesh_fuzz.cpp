// Fuzz harness: a mesh file (.3ds, .glb or .gltf, told apart by its first bytes) through the
// shared mesh loader of fixtures/mesh (GDTF body models, MVR geometry), with small limits.
#include <cstring>
#include <string>

#include "fixtures/mesh/mesh.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptMesh(const uint8_t* data, size_t size) {
  std::string name = "fuzz.3ds";
  if (size >= 4 && std::memcmp(data, "glTF", 4) == 0) name = "fuzz.glb";
  else if (size >= 1 && data[0] == '{') name = "fuzz.gltf";
  const MeshLimits limits{.maxFileBytes = 1u << 20, .maxTriangles = 100'000, .maxVertices = 200'000};
  auto mesh = loadMesh(data, size, name, limits);
  if (!mesh) return false;
  // What the body code does next: every index names a vertex, and the bounds hold them all.
  for (std::uint32_t i : mesh->indices)
    if (i >= mesh->positions.size()) __builtin_trap();
  if (mesh->normals.size() != mesh->positions.size()) __builtin_trap();
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptMesh)
