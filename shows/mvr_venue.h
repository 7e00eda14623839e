// The MVR importer's venue writer: the scene's .3ds and .glb geometry, each file read once with
// assimp and placed by node matrices, written as one glTF (.gltf + .bin) in haze's frame.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "fixtures/result.h"

namespace haze {

class ZipArchive;

struct MvrGeometryInstance {
  std::string fileName;   // the archive entry (.3ds in mm, Z-up; .glb in metres, Y-up)
  glm::dmat4 worldMm;     // local -> MVR world (mm)
  std::string place;      // XML place for warnings
};

struct MvrVenueStats {
  int instances = 0;      // placed
  int meshes = 0;         // distinct files that gave triangles
  std::size_t triangles = 0;
};

// Writes gltfFile and gltfFile with .bin; problems with single files are warnings (that
// geometry is left out), only a failed write is an Error.
Result<MvrVenueStats> writeMvrVenue(const ZipArchive& archive, const std::vector<MvrGeometryInstance>& instances,
                                    const std::filesystem::path& gltfFile, std::size_t maxTriangles,
                                    std::vector<std::string>& warnings);

}  // namespace haze
