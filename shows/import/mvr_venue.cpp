// Builds the venue glTF of an MVR import: every distinct geometry file becomes one glTF mesh in
// its own units and axes, and every placement of it a node whose matrix takes it into haze's
// frame (Y-up metres). Instancing keeps a rig of 2000 truss pieces small on disk.
#include "shows/import/mvr_venue.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "fixtures/core/zip_archive.h"
#include "fixtures/mesh/mesh.h"
#include "shows/show_save.h"

namespace haze {

namespace {

// Placed triangles kept for the camera's rays (36 bytes each): symbols of symbols can place a
// stored mesh 200000 times, which must not become gigabytes.
constexpr std::size_t kMaxPlacedTriangles = 2'000'000;

std::string lowerExt(const std::string& name) { return meshExtension(name); }

// One file through the shared mesh loader (fixtures/mesh), node transforms baked in; an error
// sentence when it gives nothing.
std::string readGeometryFile(const ZipArchive& archive, const std::string& name, std::size_t budgetTriangles, TriangleMesh& out) {
  if (!isMeshFile(name)) return "geometry file \"" + name + "\" is neither .3ds nor .glb; left out";
  auto bytes = archive.read(name);
  if (!bytes.ok()) return "geometry file \"" + name + "\" cannot be read (" + bytes.error().message + "); left out";
  MeshLimits limits;
  limits.maxTriangles = budgetTriangles;
  limits.maxFileBytes = std::size_t{1} << 30;  // the archive reader has its own limits
  auto mesh = loadMesh(bytes->data(), bytes->size(), name, limits);
  if (!mesh.ok()) {
    if (mesh.error().message.starts_with("has more than") && mesh.error().message.ends_with("triangles"))
      return "geometry file \"" + name + "\" would pass the venue's triangle limit; left out";
    return "geometry file \"" + name + "\" " + mesh.error().message + "; left out";
  }
  out = std::move(*mesh);
  return "";
}

void appendBytes(std::string& bin, const void* data, std::size_t bytes) {
  bin.append(static_cast<const char*>(data), bytes);
  while (bin.size() % 4 != 0) bin.push_back('\0');
}

}  // namespace

Result<MvrVenueStats> writeMvrVenue(const ZipArchive& archive, const std::vector<MvrGeometryInstance>& instances,
                                    const std::filesystem::path& gltfFile, std::size_t maxTriangles,
                                    std::vector<std::string>& warnings) {
  // MVR world (mm, Z-up) -> haze (m, Y-up): (x, y, z) -> (x, z, -y) / 1000.
  glm::dmat4 mvrToHaze(0.0);
  mvrToHaze[0][0] = 1e-3;
  mvrToHaze[1][2] = -1e-3;
  mvrToHaze[2][1] = 1e-3;
  mvrToHaze[3][3] = 1.0;
  // Y-up file frame -> MVR local (Z-up): (x, y, z) -> (x, -z, y). glTF files need it with a
  // scale (metres -> mm); .3ds files need it too, without the scale, because assimp's 3DS
  // loader turns the file's Z-up into Y-up with (x, y, z) -> (x, z, -y) on its root node, which
  // aiProcess_PreTransformVertices bakes into the vertices.
  glm::dmat4 yUpToMvr(0.0);
  yUpToMvr[0][0] = 1.0;
  yUpToMvr[1][2] = 1.0;
  yUpToMvr[2][1] = -1.0;
  yUpToMvr[3][3] = 1.0;
  const glm::dmat4 gltfToMvr = yUpToMvr * glm::dmat4(glm::dmat3(1e3));

  MvrVenueStats stats;
  std::map<std::string, int> meshIndex;  // file -> glTF mesh, -1 when it failed
  std::vector<TriangleMesh> loaded;          // by glTF mesh, for the placed triangles
  std::string bin;
  nlohmann::json accessors = nlohmann::json::array(), views = nlohmann::json::array(),
                 meshes = nlohmann::json::array(), nodes = nlohmann::json::array();
  std::size_t stored = 0;
  auto addView = [&](const void* data, std::size_t bytes, int target) {
    nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}, {"target", target}};
    appendBytes(bin, data, bytes);
    views.push_back(v);
    return static_cast<int>(views.size() - 1);
  };
  for (const MvrGeometryInstance& inst : instances) {
    auto it = meshIndex.find(inst.fileName);
    if (it == meshIndex.end()) {
      TriangleMesh mesh;
      const std::string problem = readGeometryFile(archive, inst.fileName, maxTriangles - stored, mesh);
      if (!problem.empty()) {
        warnings.push_back(inst.place + ": " + problem);
        it = meshIndex.emplace(inst.fileName, -1).first;
      } else {
        stored += mesh.indices.size() / 3;
        const glm::vec3 lo = mesh.boundsMin, hi = mesh.boundsMax;
        const std::size_t nVerts = mesh.positions.size();
        const int pv = addView(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3), 34962);
        const int nv = addView(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3), 34962);
        const int iv = addView(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t), 34963);
        accessors.push_back({{"bufferView", pv}, {"componentType", 5126}, {"count", nVerts}, {"type", "VEC3"},
                             {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}});
        accessors.push_back({{"bufferView", nv}, {"componentType", 5126}, {"count", nVerts}, {"type", "VEC3"}});
        accessors.push_back({{"bufferView", iv}, {"componentType", 5125}, {"count", mesh.indices.size()}, {"type", "SCALAR"}});
        const int a0 = static_cast<int>(accessors.size()) - 3;
        meshes.push_back({{"name", inst.fileName},
                          {"primitives", {{{"attributes", {{"POSITION", a0}, {"NORMAL", a0 + 1}}},
                                           {"indices", a0 + 2}, {"material", 0}, {"mode", 4}}}}});
        it = meshIndex.emplace(inst.fileName, static_cast<int>(meshes.size() - 1)).first;
        ++stats.meshes;
        if (lowerExt(inst.fileName) != "3ds") meshes.back()["extras"] = {{"mvr_units", "m, Y-up"}};
        else meshes.back()["extras"] = {{"mvr_units", "mm, Y-up (assimp turned the .3ds Z-up)"}};
        stats.triangles += mesh.indices.size() / 3;
        mesh.normals.clear();
        mesh.normals.shrink_to_fit();
        loaded.push_back(std::move(mesh));
      }
    }
    if (it->second < 0) continue;
    const bool yUp = lowerExt(inst.fileName) != "3ds";  // glTF: metres
    const glm::dmat4 m = mvrToHaze * inst.worldMm * (yUp ? gltfToMvr : yUpToMvr);
    nlohmann::json matrix = nlohmann::json::array();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) matrix.push_back(static_cast<double>(static_cast<float>(m[c][r])));
    nodes.push_back({{"name", inst.place}, {"mesh", it->second}, {"matrix", matrix}});
    const TriangleMesh& placed = loaded[static_cast<std::size_t>(it->second)];
    if (stats.placedTrianglesM.size() + placed.indices.size() <= 3 * kMaxPlacedTriangles) {
      for (std::uint32_t index : placed.indices) {
        const glm::vec3& p = placed.positions[index];
        stats.placedTrianglesM.push_back(glm::vec3(m * glm::dvec4(p.x, p.y, p.z, 1.0)));
      }
    } else if (!stats.placedTrianglesCut) {
      stats.placedTrianglesCut = true;
      warnings.push_back(inst.place + ": the venue places more than " + std::to_string(kMaxPlacedTriangles) +
                         " triangles; the overview camera is placed against the first ones only (the venue itself is complete)");
    }
    ++stats.instances;
  }

  const std::string binName = gltfFile.stem().string() + ".bin";
  nlohmann::json sceneNodes = nlohmann::json::array();
  for (std::size_t i = 0; i < nodes.size(); ++i) sceneNodes.push_back(i);
  nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "haze import-mvr"}}},
      {"scene", 0},
      {"scenes", {{{"name", "MVR venue"}, {"nodes", sceneNodes}}}},
      {"nodes", nodes},
      {"materials", {{{"name", "MVR geometry"},
                      {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.6, 0.6, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}},
                      {"doubleSided", true}}}},
  };
  if (!meshes.empty()) {
    gltf["meshes"] = meshes;
    gltf["accessors"] = accessors;
    gltf["bufferViews"] = views;
    gltf["buffers"] = {{{"uri", binName}, {"byteLength", bin.size()}}};
  }
  if (nodes.empty()) gltf["scenes"][0].erase("nodes");
  if (!meshes.empty()) {
    Status s = writeFileAtomically(gltfFile.parent_path() / binName, bin, false);
    if (!s.ok()) return s.error();
  }
  Status s = writeFileAtomically(gltfFile, gltf.dump(1), false);
  if (!s.ok()) return s.error();
  return stats;
}

Result<MvrVenueStats> writeMvrFloorVenue(const std::filesystem::path& gltfFile, const glm::vec2& loM, const glm::vec2& hiM) {
  const float positions[12] = {loM.x, 0, loM.y, hiM.x, 0, loM.y, hiM.x, 0, hiM.y, loM.x, 0, hiM.y};
  const float normals[12] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
  const std::uint32_t indices[6] = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
  std::string bin;
  appendBytes(bin, positions, sizeof positions);
  appendBytes(bin, normals, sizeof normals);
  appendBytes(bin, indices, sizeof indices);
  const std::string binName = gltfFile.stem().string() + ".bin";
  const nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "haze import-mvr (floor: the MVR has no geometry)"}}},
      {"scene", 0},
      {"scenes", {{{"name", "MVR floor"}, {"nodes", {0}}}}},
      {"nodes", {{{"name", "floor at MVR z = 0"}, {"mesh", 0}}}},
      {"meshes", {{{"name", "floor"}, {"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"material", 0}, {"mode", 4}}}}}}},
      {"materials", {{{"name", "MVR floor"},
                      {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.6, 0.6, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}},
                      {"doubleSided", true}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                      {"min", {loM.x, 0.0f, loM.y}}, {"max", {hiM.x, 0.0f, hiM.y}}},
                     {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                     {{"bufferView", 2}, {"componentType", 5125}, {"count", 6}, {"type", "SCALAR"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof positions}, {"target", 34962}},
                       {{"buffer", 0}, {"byteOffset", sizeof positions}, {"byteLength", sizeof normals}, {"target", 34962}},
                       {{"buffer", 0}, {"byteOffset", sizeof positions + sizeof normals}, {"byteLength", sizeof indices}, {"target", 34963}}}},
      {"buffers", {{{"uri", binName}, {"byteLength", bin.size()}}}},
  };
  Status s = writeFileAtomically(gltfFile.parent_path() / binName, bin, false);
  if (!s.ok()) return s.error();
  s = writeFileAtomically(gltfFile, gltf.dump(1), false);
  if (!s.ok()) return s.error();
  MvrVenueStats stats;
  stats.instances = 1;
  stats.meshes = 1;
  stats.triangles = 2;
  for (std::uint32_t i : indices) stats.placedTrianglesM.push_back({positions[3 * i], 0.0f, positions[3 * i + 2]});
  return stats;
}

}  // namespace haze
