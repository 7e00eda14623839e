// The MVR importer's venue writer: the scene's .3ds and .glb geometry, each file read once with
// assimp and placed by node matrices, written as one glTF (.gltf + .bin) in haze's frame.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fixtures/core/result.h"

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
  // Every placed triangle in haze's frame (metres, 3 corners each): the importer casts rays
  // against them to put its camera inside an enclosed venue (shows/import/mvr_camera.h).
  std::vector<glm::vec3> placedTrianglesM;
  bool placedTrianglesCut = false;  // more than 2 million placed: the rest are not in the list
};

// Writes gltfFile and gltfFile with .bin; problems with single files are warnings (that
// geometry is left out), only a failed write is an Error.
Result<MvrVenueStats> writeMvrVenue(const ZipArchive& archive, const std::vector<MvrGeometryInstance>& instances,
                                    const std::filesystem::path& gltfFile, std::size_t maxTriangles,
                                    std::vector<std::string>& warnings);

// For an MVR without geometry: a floor at haze y = 0 (MVR z = 0, where MVR exports put the
// stage floor) over loM..hiM in x and z, as a venue glTF with one quad, so that a render of the
// imported show has somewhere for the beams to land. Only a failed write is an Error.
Result<MvrVenueStats> writeMvrFloorVenue(const std::filesystem::path& gltfFile, const glm::vec2& loM, const glm::vec2& hiM);

}  // namespace haze
