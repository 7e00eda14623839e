// glTF 2.0 -> Venue: walks the default scene's node tree, applies node transforms, and flattens
// every triangle primitive to world space, so the GPU and the CPU reference see the same
// triangles. tinygltf does the parsing (Debian ships it as a shared library).
#include "renderer/scene/venue.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

namespace haze {
namespace {

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

glm::mat4 nodeMatrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(n.matrix[i]);
    return m;  // glTF matrices are column-major, as glm's
  }
  glm::mat4 m(1.0f);
  if (n.translation.size() == 3)
    m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
  if (n.rotation.size() == 4) {
    const glm::quat q(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                      static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
    m = m * glm::mat4_cast(q);
  }
  if (n.scale.size() == 3)
    m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
  return m;
}

// Reads accessor element i as up to 4 floats (normalised integers are mapped to [0, 1]).
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int index) {
    if (index < 0 || index >= static_cast<int>(model.accessors.size())) return;
    acc_ = &model.accessors[index];
    if (acc_->bufferView < 0 || acc_->bufferView >= static_cast<int>(model.bufferViews.size())) {
      acc_ = nullptr;
      return;
    }
    const tinygltf::BufferView& view = model.bufferViews[acc_->bufferView];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) {
      acc_ = nullptr;
      return;
    }
    const tinygltf::Buffer& buf = model.buffers[view.buffer];
    components_ = tinygltf::GetNumComponentsInType(acc_->type);
    componentBytes_ = tinygltf::GetComponentSizeInBytes(acc_->componentType);
    if (components_ <= 0 || componentBytes_ <= 0) {
      acc_ = nullptr;
      return;
    }
    stride_ = acc_->ByteStride(view);
    const size_t start = view.byteOffset + acc_->byteOffset;
    const size_t elemBytes = static_cast<size_t>(components_) * componentBytes_;
    // Bounds: the last element must end inside the view and the buffer.
    if (stride_ <= 0 || acc_->count == 0 ||
        acc_->byteOffset + (acc_->count - 1) * static_cast<size_t>(stride_) + elemBytes > view.byteLength ||
        view.byteOffset + view.byteLength > buf.data.size()) {
      acc_ = nullptr;
      return;
    }
    data_ = buf.data.data() + start;
  }

  bool ok() const { return acc_ != nullptr; }
  size_t count() const { return acc_ ? acc_->count : 0; }
  int components() const { return components_; }

  float component(size_t i, int c) const {
    const unsigned char* p = data_ + i * static_cast<size_t>(stride_) + c * componentBytes_;
    switch (acc_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return acc_->normalized ? *p / 255.0f : *p;
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<signed char>(*p);
        return acc_->normalized ? std::max(v / 127.0f, -1.0f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v; std::memcpy(&v, p, 2); return acc_->normalized ? v / 65535.0f : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v; std::memcpy(&v, p, 2); return acc_->normalized ? std::max(v / 32767.0f, -1.0f) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p, 4); return static_cast<float>(v); }
      default: return 0.0f;
    }
  }
  uint32_t index(size_t i) const {
    const unsigned char* p = data_ + i * static_cast<size_t>(stride_);
    switch (acc_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p, 4); return v; }
      default: return std::numeric_limits<uint32_t>::max();
    }
  }

 private:
  const tinygltf::Accessor* acc_ = nullptr;
  const unsigned char* data_ = nullptr;
  int components_ = 0;
  int componentBytes_ = 0;
  int stride_ = 0;
};

struct Loader {
  const tinygltf::Model& model;
  Venue& venue;
  std::string fileName;
  std::string error;
  int depth = 0;

  int texture(int gltfTexture, bool srgb) {
    if (gltfTexture < 0 || gltfTexture >= static_cast<int>(model.textures.size())) return -1;
    const int source = model.textures[gltfTexture].source;
    if (source < 0 || source >= static_cast<int>(model.images.size())) return -1;
    const tinygltf::Image& img = model.images[source];
    if (img.width <= 0 || img.height <= 0 || img.image.empty()) return -1;
    // tinygltf decodes to img.component channels of img.bits bits; haze keeps RGBA8.
    Texture t;
    t.name = img.name.empty() ? img.uri : img.name;
    t.width = img.width;
    t.height = img.height;
    t.srgb = srgb;
    const size_t n = static_cast<size_t>(img.width) * img.height;
    const int comps = img.component;
    const int bytesPer = img.bits == 16 ? 2 : 1;
    if (comps < 1 || comps > 4 || img.image.size() < n * comps * bytesPer) return -1;
    t.rgba8.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
      unsigned char px[4] = {0, 0, 0, 255};
      for (int c = 0; c < comps; ++c) {
        const size_t at = (i * comps + c) * bytesPer;
        px[c] = bytesPer == 2 ? img.image[at + 1] : img.image[at];  // little-endian high byte
      }
      if (comps == 1 || comps == 2) {  // grey (+alpha)
        px[3] = comps == 2 ? px[1] : 255;
        px[1] = px[2] = px[0];
      }
      std::memcpy(&t.rgba8[i * 4], px, 4);
    }
    venue.textures.push_back(std::move(t));
    return static_cast<int>(venue.textures.size()) - 1;
  }

  void materials() {
    venue.materials.push_back(Material{.name = "default"});
    for (const tinygltf::Material& m : model.materials) {
      Material out;
      out.name = m.name;
      const auto& f = m.pbrMetallicRoughness.baseColorFactor;
      if (f.size() == 4) out.baseColor = glm::vec4(f[0], f[1], f[2], f[3]);
      out.baseColorTexture = texture(m.pbrMetallicRoughness.baseColorTexture.index, true);
      if (m.emissiveFactor.size() == 3)
        out.emissive = glm::vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
      auto ext = m.extensions.find("KHR_materials_emissive_strength");
      if (ext != m.extensions.end() && ext->second.Has("emissiveStrength"))
        out.emissive *= static_cast<float>(ext->second.Get("emissiveStrength").GetNumberAsDouble());
      out.emissiveTexture = texture(m.emissiveTexture.index, true);
      venue.materials.push_back(std::move(out));
    }
  }

  bool primitive(const tinygltf::Primitive& p, const glm::mat4& world, const std::string& name) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) return true;  // points/lines: not surfaces
    auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) return true;
    AccessorReader positions(model, pos->second);
    if (!positions.ok() || positions.components() != 3) {
      error = "mesh '" + name + "': POSITION accessor is out of its buffer or not VEC3";
      return false;
    }
    Primitive out;
    out.name = name;
    out.material = p.material >= 0 && p.material + 1 < static_cast<int>(venue.materials.size())
                       ? p.material + 1 : 0;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    const size_t n = positions.count();
    out.positions.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const glm::vec4 v(positions.component(i, 0), positions.component(i, 1), positions.component(i, 2), 1.0f);
      out.positions[i] = glm::vec3(world * v);
    }
    if (auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
      AccessorReader normals(model, it->second);
      if (normals.ok() && normals.count() == n && normals.components() == 3) {
        out.normals.resize(n);
        for (size_t i = 0; i < n; ++i) {
          const glm::vec3 nn = normalMatrix * glm::vec3(normals.component(i, 0), normals.component(i, 1),
                                                        normals.component(i, 2));
          const float len = glm::length(nn);
          out.normals[i] = len > 0.0f ? nn / len : glm::vec3(0.0f, 1.0f, 0.0f);
        }
      }
    }
    if (auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end()) {
      AccessorReader uvs(model, it->second);
      if (uvs.ok() && uvs.count() == n && uvs.components() == 2) {
        out.uvs.resize(n);
        for (size_t i = 0; i < n; ++i) out.uvs[i] = glm::vec2(uvs.component(i, 0), uvs.component(i, 1));
      }
    }
    if (p.indices >= 0) {
      AccessorReader idx(model, p.indices);
      if (!idx.ok() || idx.components() != 1) {
        error = "mesh '" + name + "': indices accessor is out of its buffer or not SCALAR";
        return false;
      }
      out.indices.resize(idx.count());
      for (size_t i = 0; i < idx.count(); ++i) {
        out.indices[i] = idx.index(i);
        if (out.indices[i] >= n) {
          error = "mesh '" + name + "': index " + std::to_string(out.indices[i]) + " past the " +
                  std::to_string(n) + " vertices";
          return false;
        }
      }
    } else {
      out.indices.resize(n);
      for (size_t i = 0; i < n; ++i) out.indices[i] = static_cast<uint32_t>(i);
    }
    out.indices.resize(out.indices.size() / 3 * 3);
    // A mirroring transform flips the winding; keep triangles counter-clockwise as glTF says.
    if (glm::determinant(glm::mat3(world)) < 0.0f)
      for (size_t t = 0; t + 2 < out.indices.size(); t += 3) std::swap(out.indices[t + 1], out.indices[t + 2]);
    if (out.normals.empty()) flatNormals(out);
    if (!out.indices.empty()) venue.primitives.push_back(std::move(out));
    return true;
  }

  // Without normals in the file, each triangle gets its face normal (vertices are split).
  static void flatNormals(Primitive& p) {
    Primitive flat;
    flat.name = p.name;
    flat.material = p.material;
    for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
      const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]],
                      c = p.positions[p.indices[t + 2]];
      glm::vec3 nn = glm::cross(b - a, c - a);
      const float len = glm::length(nn);
      nn = len > 0.0f ? nn / len : glm::vec3(0.0f, 1.0f, 0.0f);
      for (int k = 0; k < 3; ++k) {
        const uint32_t src = p.indices[t + k];
        flat.positions.push_back(p.positions[src]);
        flat.normals.push_back(nn);
        if (!p.uvs.empty()) flat.uvs.push_back(p.uvs[src]);
        flat.indices.push_back(static_cast<uint32_t>(flat.indices.size()));
      }
    }
    p = std::move(flat);
  }

  bool node(int index, const glm::mat4& parent) {
    if (index < 0 || index >= static_cast<int>(model.nodes.size())) {
      error = "node index " + std::to_string(index) + " does not exist";
      return false;
    }
    if (++depth > 256) {  // a cycle in the node graph would recurse forever
      error = "node tree deeper than 256 levels (a cycle?)";
      return false;
    }
    const tinygltf::Node& n = model.nodes[index];
    const glm::mat4 world = parent * nodeMatrix(n);
    if (n.mesh >= 0 && n.mesh < static_cast<int>(model.meshes.size())) {
      const tinygltf::Mesh& mesh = model.meshes[n.mesh];
      const std::string name = !n.name.empty() ? n.name : mesh.name;
      for (const tinygltf::Primitive& p : mesh.primitives)
        if (!primitive(p, world, name)) return false;
    }
    for (int child : n.children)
      if (!node(child, world)) return false;
    --depth;
    return true;
  }
};

}  // namespace

glm::vec4 Texture::sampleLinear(glm::vec2 uv) const {
  if (width <= 0 || height <= 0) return glm::vec4(1.0f);
  const float x = (uv.x - std::floor(uv.x)) * width - 0.5f;
  const float y = (uv.y - std::floor(uv.y)) * height - 0.5f;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - x0, fy = y - y0;
  auto texel = [&](int tx, int ty) {
    tx = ((tx % width) + width) % width;
    ty = ((ty % height) + height) % height;
    const unsigned char* p = &rgba8[(static_cast<size_t>(ty) * width + tx) * 4];
    glm::vec4 c(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f);
    if (srgb) c = glm::vec4(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a);
    return c;
  };
  return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), fx),
                  glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx), fy);
}

size_t Venue::triangleCount() const {
  size_t n = 0;
  for (const Primitive& p : primitives) n += p.indices.size() / 3;
  return n;
}

glm::vec3 Venue::albedo(const Primitive& p, glm::vec2 uv) const {
  const Material& m = materials.at(static_cast<size_t>(p.material));
  glm::vec3 c(m.baseColor);
  if (m.baseColorTexture >= 0) c *= glm::vec3(textures[m.baseColorTexture].sampleLinear(uv));
  return c;
}

glm::vec3 Venue::emission(const Primitive& p, glm::vec2 uv) const {
  const Material& m = materials.at(static_cast<size_t>(p.material));
  glm::vec3 e = m.emissive;
  if (m.emissiveTexture >= 0) e *= glm::vec3(textures[m.emissiveTexture].sampleLinear(uv));
  return e;
}

Result<Venue> loadVenue(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    return Error{name, "", "venue file not found (expected a .gltf or .glb file)"};
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const std::string ext = file.extension().string();
  bool ok = false;
  try {
    ok = (ext == ".glb" || ext == ".GLB") ? loader.LoadBinaryFromFile(&model, &err, &warn, name)
                                          : loader.LoadASCIIFromFile(&model, &err, &warn, name);
  } catch (const std::exception& e) {
    err = e.what();
  }
  if (!ok) {
    std::string first = err.substr(0, err.find('\n'));
    if (first.empty()) first = "not a valid glTF 2.0 file";
    return Error{name, "", "cannot read glTF: " + first};
  }
  Venue venue;
  venue.file = file;
  Loader l{model, venue, name, {}, 0};
  l.materials();
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (sceneIndex < static_cast<int>(model.scenes.size())) {
    for (int root : model.scenes[sceneIndex].nodes)
      if (!l.node(root, glm::mat4(1.0f))) return Error{name, "", l.error};
  } else {
    for (size_t i = 0; i < model.nodes.size(); ++i)  // no scene: every node is a root
      if (!l.node(static_cast<int>(i), glm::mat4(1.0f))) return Error{name, "", l.error};
  }
  if (venue.primitives.empty()) return Error{name, "", "the glTF has no triangle meshes to draw"};
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Primitive& p : venue.primitives)
    for (const glm::vec3& v : p.positions) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  venue.boundsMin = lo;
  venue.boundsMax = hi;
  return venue;
}

Venue venueFromTriangles(std::vector<glm::vec3> trianglesM) {
  Venue v;
  v.materials.emplace_back();
  trianglesM.resize(trianglesM.size() / 3 * 3);
  if (trianglesM.empty()) return v;
  Primitive p;
  p.name = "triangles";
  p.indices.resize(trianglesM.size());
  for (size_t i = 0; i < trianglesM.size(); ++i) p.indices[i] = static_cast<uint32_t>(i);
  glm::vec3 lo(trianglesM[0]), hi(trianglesM[0]);
  for (const glm::vec3& q : trianglesM) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  p.normals.resize(trianglesM.size());
  for (size_t i = 0; i < trianglesM.size(); i += 3) {
    const glm::vec3 n = glm::cross(trianglesM[i + 1] - trianglesM[i], trianglesM[i + 2] - trianglesM[i]);
    const float len = glm::length(n);
    p.normals[i] = p.normals[i + 1] = p.normals[i + 2] = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
  }
  p.positions = std::move(trianglesM);
  v.primitives.push_back(std::move(p));
  v.boundsMin = lo;
  v.boundsMax = hi;
  return v;
}

}  // namespace haze
