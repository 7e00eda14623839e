// glTF 2.0 -> Venue: walks the default scene's node tree, applies node transforms, and flattens
// every triangle primitive to world space, so the GPU and the CPU reference see the same
// triangles. tinygltf does the parsing (Debian ships it as a shared library).
#include "shows/scene/venue.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <stb_image.h>
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

// Overflow-checked size arithmetic: every offset, count and stride below comes from the file,
// and a sum that wraps past 2^64 would pass any bounds check.
bool addOk(size_t a, size_t b, size_t& out) { return !__builtin_add_overflow(a, b, &out); }
bool mulOk(size_t a, size_t b, size_t& out) { return !__builtin_mul_overflow(a, b, &out); }

// Reads accessor element i as up to 4 floats (normalised integers are mapped to [0, 1]).
// Construction checks that every element lies inside its buffer view and the view inside its
// buffer; error() says which bound failed.
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int index) {
    const std::string at = "accessors[" + std::to_string(index) + "]";
    if (index < 0 || index >= static_cast<int>(model.accessors.size())) {
      error_ = at + " does not exist (" + std::to_string(model.accessors.size()) + " accessors)";
      return;
    }
    const tinygltf::Accessor& acc = model.accessors[static_cast<size_t>(index)];
    if (acc.bufferView < 0 || acc.bufferView >= static_cast<int>(model.bufferViews.size())) {
      error_ = at + ": bufferView " + std::to_string(acc.bufferView) + " does not exist";
      return;
    }
    const std::string viewAt = "bufferViews[" + std::to_string(acc.bufferView) + "]";
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(acc.bufferView)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) {
      error_ = viewAt + ": buffer " + std::to_string(view.buffer) + " does not exist";
      return;
    }
    const tinygltf::Buffer& buf = model.buffers[static_cast<size_t>(view.buffer)];
    size_t viewEnd = 0;
    if (!addOk(view.byteOffset, view.byteLength, viewEnd) || viewEnd > buf.data.size()) {
      error_ = viewAt + ": byteOffset + byteLength exceeds buffers[" + std::to_string(view.buffer) + "] (" +
               std::to_string(buf.data.size()) + " bytes)";
      return;
    }
    components_ = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(acc.type));
    componentBytes_ = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType));
    if (components_ <= 0 || componentBytes_ <= 0) {
      error_ = at + ": unknown type or componentType";
      return;
    }
    const size_t elemBytes = static_cast<size_t>(components_) * static_cast<size_t>(componentBytes_);
    // glTF: byteStride 0 (or absent) means tightly packed; tinygltf's ByteStride() gives -1 for
    // a stride it deems invalid, which would read as a huge size_t here.
    const size_t stride = view.byteStride == 0 ? elemBytes : view.byteStride;
    if (acc.count == 0) {
      error_ = at + ": count is 0";
      return;
    }
    // The last element must end inside the view: byteOffset + (count - 1) * stride + elemBytes.
    size_t span = 0, end = 0;
    if (!mulOk(acc.count - 1, stride, span) || !addOk(span, acc.byteOffset, end) || !addOk(end, elemBytes, end) ||
        end > view.byteLength) {
      error_ = at + ": byteOffset + count * stride exceeds " + viewAt + " (" + std::to_string(view.byteLength) +
               " bytes)";
      return;
    }
    acc_ = &acc;
    stride_ = stride;
    count_ = acc.count;
    data_ = buf.data.data() + view.byteOffset + acc.byteOffset;
  }

  bool ok() const { return acc_ != nullptr; }
  const std::string& error() const { return error_; }
  size_t count() const { return count_; }
  int components() const { return components_; }

  float component(size_t i, int c) const {
    const unsigned char* p = data_ + i * stride_ + static_cast<size_t>(c * componentBytes_);
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
    const unsigned char* p = data_ + i * stride_;
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
  size_t stride_ = 0;
  size_t count_ = 0;
  std::string error_;
};

struct Loader {
  const tinygltf::Model& model;
  Venue& venue;
  const VenueLimits& limits;
  std::string error;
  int depth = 0;
  size_t nodeVisits = 0;
  size_t vertices = 0;   // stored so far, over all primitives
  size_t triangles = 0;

  // Claims room for a primitive before it is allocated.
  bool reserve(const std::string& name, size_t addVertices, size_t addTriangles) {
    if (addVertices > limits.maxVertices - vertices) {
      error = "mesh '" + name + "': the venue would hold more than " + std::to_string(limits.maxVertices) +
              " vertices (the limit)";
      return false;
    }
    if (addTriangles > limits.maxTriangles - triangles) {
      error = "mesh '" + name + "': the venue would hold more than " + std::to_string(limits.maxTriangles) +
              " triangles (the limit)";
      return false;
    }
    vertices += addVertices;
    triangles += addTriangles;
    return true;
  }

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
    const size_t n = static_cast<size_t>(img.width) * static_cast<size_t>(img.height);
    const int comps = img.component;
    const int bytesPer = img.bits == 16 ? 2 : 1;
    if (n > kMaxVenueTexturePixels || comps < 1 || comps > 4 ||
        img.image.size() < n * static_cast<size_t>(comps * bytesPer))
      return -1;
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
    if (!positions.ok()) {
      error = "mesh '" + name + "' POSITION: " + positions.error();
      return false;
    }
    if (positions.components() != 3) {
      error = "mesh '" + name + "' POSITION: accessors[" + std::to_string(pos->second) + "] is not VEC3";
      return false;
    }
    Primitive out;
    out.name = name;
    // Compared without the +1 so that material = INT_MAX from a file cannot overflow.
    out.material = p.material >= 0 && p.material < static_cast<int>(venue.materials.size()) - 1
                       ? p.material + 1 : 0;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    const size_t n = positions.count();
    std::optional<AccessorReader> idx;
    if (p.indices >= 0) {
      idx.emplace(model, p.indices);
      if (!idx->ok()) {
        error = "mesh '" + name + "' indices: " + idx->error();
        return false;
      }
      if (idx->components() != 1) {
        error = "mesh '" + name + "' indices: accessors[" + std::to_string(p.indices) + "] is not SCALAR";
        return false;
      }
    }
    if (!reserve(name, n, (idx ? idx->count() : n) / 3)) return false;
    out.positions.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const glm::vec4 v(positions.component(i, 0), positions.component(i, 1), positions.component(i, 2), 1.0f);
      out.positions[i] = glm::vec3(world * v);
      // A NaN or infinite corner would poison the bounds and the BVH built from them.
      if (!std::isfinite(out.positions[i].x) || !std::isfinite(out.positions[i].y) ||
          !std::isfinite(out.positions[i].z)) {
        error = "mesh '" + name + "' POSITION: accessors[" + std::to_string(pos->second) + "] element " +
                std::to_string(i) + " is not finite in world space";
        return false;
      }
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
    if (idx) {
      out.indices.resize(idx->count());
      for (size_t i = 0; i < idx->count(); ++i) {
        out.indices[i] = idx->index(i);
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
    // Without usable normals, flatNormals stores 3 new vertices per triangle.
    if (out.normals.empty()) {
      if (!reserve(name, out.indices.size(), 0)) return false;
      flatNormals(out);
    }
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
    // Children may be shared, so a small file can describe exponentially many instances.
    if (++nodeVisits > limits.maxNodeVisits) {
      error = "nodes[" + std::to_string(index) + "]: more than " + std::to_string(limits.maxNodeVisits) +
              " node instances (the limit; nodes shared many times over?)";
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
  // A NaN or infinite coordinate (a degenerate triangle's barycentrics, a hostile file) has no
  // texel; casting its floor to int is undefined, so it samples at 0 instead.
  if (!std::isfinite(uv.x)) uv.x = 0.0f;
  if (!std::isfinite(uv.y)) uv.y = 0.0f;
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

namespace {

// Decodes with tinygltf's own stb loader, after refusing an image whose header promises more
// pixels than a texture may hold (a 40-byte PNG can claim 2^24 x 2^24).
bool loadImageLimited(tinygltf::Image* image, const int imageIndex, std::string* err, std::string* warn, int reqWidth,
                      int reqHeight, const unsigned char* bytes, int size, void* user) {
  int w = 0, h = 0, comp = 0;
  if (stbi_info_from_memory(bytes, size, &w, &h, &comp) &&
      static_cast<size_t>(w) * static_cast<size_t>(h) > kMaxVenueTexturePixels) {
    if (err)
      *err += "images[" + std::to_string(imageIndex) + "]: " + std::to_string(w) + " x " + std::to_string(h) +
              " pixels; expected at most " + std::to_string(kMaxVenueTexturePixels) + "\n";
    return false;
  }
  return tinygltf::LoadImageData(image, imageIndex, err, warn, reqWidth, reqHeight, bytes, size, user);
}

// File access for a venue read from memory without a base folder: every external URI fails.
tinygltf::FsCallbacks noFiles() {
  tinygltf::FsCallbacks fs{};
  fs.FileExists = [](const std::string&, void*) { return false; };
  fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
  fs.ReadWholeFile = [](std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err) *err += "external file '" + path + "' is not read (in-memory venue)\n";
    return false;
  };
  fs.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
  };
  fs.user_data = nullptr;
  return fs;
}

Result<Venue> venueFromModel(const tinygltf::Model& model, const std::filesystem::path& file, const std::string& name,
                             const VenueLimits& limits) {
  Venue venue;
  venue.file = file;
  Loader l{model, venue, limits, {}, 0};
  l.materials();
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (sceneIndex < static_cast<int>(model.scenes.size())) {
    for (int root : model.scenes[static_cast<size_t>(sceneIndex)].nodes)
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

Error gltfError(const std::string& name, const std::string& err) {
  std::string first = err.substr(0, err.find('\n'));
  if (first.empty()) first = "not a valid glTF 2.0 file";
  return Error{name, "", "cannot read glTF: " + first};
}

}  // namespace

Result<Venue> loadVenue(const std::filesystem::path& file, const VenueLimits& limits) {
  const std::string name = file.string();
  // A hostile file may still exhaust memory in tinygltf or here; that is a refusal, not an abort.
  try {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      return Error{name, "", "venue file not found (expected a .gltf or .glb file)"};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(loadImageLimited, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::string ext = file.extension().string();
    const bool ok = (ext == ".glb" || ext == ".GLB") ? loader.LoadBinaryFromFile(&model, &err, &warn, name)
                                                     : loader.LoadASCIIFromFile(&model, &err, &warn, name);
    if (!ok) return gltfError(name, err);
    return venueFromModel(model, file, name, limits);
  } catch (const std::exception& e) {
    return Error{name, "", std::string("cannot load the venue: ") + e.what()};
  }
}

Result<Venue> loadVenueFromMemory(std::span<const std::uint8_t> bytes, const std::string& sourceName,
                                  const std::filesystem::path& baseDir, const VenueLimits& limits) {
  try {
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
      return Error{sourceName, "", "the venue is larger than 4 GiB"};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(loadImageLimited, nullptr);
    if (baseDir.empty()) loader.SetFsCallbacks(noFiles());
    tinygltf::Model model;
    std::string err, warn;
    const bool glb = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok = glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), size, baseDir.string())
                        : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                     size, baseDir.string());
    if (!ok) return gltfError(sourceName, err);
    return venueFromModel(model, std::filesystem::path(sourceName), sourceName, limits);
  } catch (const std::exception& e) {
    return Error{sourceName, "", std::string("cannot load the venue: ") + e.what()};
  }
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
