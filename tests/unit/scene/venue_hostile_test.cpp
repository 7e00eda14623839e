// Hand-made hostile glTF files (built here: JSON with base64 data URIs, written to a temporary
// folder or kept in memory) must give one clean Error naming the file and the place: offsets
// that wrap past 2^64, counts no buffer holds, node graphs that instance without end. Also:
// NaN texture coordinates sample without undefined behaviour.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "shows/scene/venue.h"

namespace haze {
namespace {

using json = nlohmann::json;

std::string base64(const std::vector<uint8_t>& in) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    uint32_t v = static_cast<uint32_t>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<uint32_t>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= in[i + 2];
    out += abc[(v >> 18) & 63];
    out += abc[(v >> 12) & 63];
    out += i + 1 < in.size() ? abc[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? abc[v & 63] : '=';
  }
  return out;
}

void append(std::vector<uint8_t>& b, const void* p, size_t n) {
  const auto* c = static_cast<const uint8_t*>(p);
  b.insert(b.end(), c, c + n);
}

// One triangle: positions (36 bytes, view 0), uvs (24 bytes, view 1), uint16 indices (view 2).
struct Tri {
  std::vector<uint8_t> buffer;
  json doc;
  explicit Tri(const float uv[6] = nullptr) {
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float uvDefault[6] = {0, 0, 1, 0, 0, 1};
    const uint16_t idx[4] = {0, 1, 2, 0};
    append(buffer, pos, sizeof pos);
    append(buffer, uv ? uv : uvDefault, 24);
    append(buffer, idx, sizeof idx);
    doc = {{"asset", {{"version", "2.0"}}},
           {"scene", 0},
           {"scenes", {{{"nodes", {0}}}}},
           {"nodes", {{{"mesh", 0}}}},
           {"meshes", {{{"name", "tri"},
                        {"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}}}}}}},
           {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                            {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}},
                            {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 6}}}},
           {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                          {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
                          {{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}}};
  }
  std::string text() const {
    json d = doc;
    d["buffers"] = {{{"byteLength", buffer.size()},
                     {"uri", "data:application/octet-stream;base64," + base64(buffer)}}};
    return d.dump();
  }
};

struct TempFile {
  std::filesystem::path path;
  TempFile(const std::string& name, const std::string& text)
      : path(std::filesystem::temp_directory_path() / ("haze-venue-hostile-" + std::to_string(::getpid()) + "-" + name)) {
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

// Loads the text both ways (file and memory) and checks that both refuse it with `place`.
void expectRefused(const std::string& name, const std::string& text, const std::string& place) {
  TempFile f(name, text);
  auto fromFile = loadVenue(f.path);
  ASSERT_FALSE(fromFile.ok()) << name << " loaded";
  EXPECT_EQ(fromFile.error().file, f.path.string());
  EXPECT_NE(fromFile.error().str().find(place), std::string::npos) << fromFile.error().str();
  EXPECT_EQ(fromFile.error().str().find('\n'), std::string::npos) << "one line: " << fromFile.error().str();
  const auto* bytes = reinterpret_cast<const uint8_t*>(text.data());
  auto fromMemory = loadVenueFromMemory(std::span<const uint8_t>(bytes, text.size()), name);
  ASSERT_FALSE(fromMemory.ok());
  EXPECT_EQ(fromMemory.error().file, name);
  EXPECT_NE(fromMemory.error().str().find(place), std::string::npos) << fromMemory.error().str();
}

TEST(VenueHostile, TheTriangleItselfLoads) {
  Tri t;
  TempFile f("ok.gltf", t.text());
  auto v = loadVenue(f.path);
  ASSERT_TRUE(v.ok()) << v.error().str();
  EXPECT_EQ(v->triangleCount(), 1u);
  const std::string text = t.text();
  auto m = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()), "mem");
  ASSERT_TRUE(m.ok()) << m.error().str();
  EXPECT_EQ(m->triangleCount(), 1u);
  EXPECT_EQ(m->primitives[0].uvs.size(), 3u);
}

TEST(VenueHostile, AccessorOffsetThatWrapsPast2To64IsRefused) {
  Tri t;
  // 2^64 - 12: added to the view's offset it wraps to 12 bytes before the buffer.
  t.doc["accessors"][0]["byteOffset"] = std::numeric_limits<uint64_t>::max() - 11;
  expectRefused("wrap.gltf", t.text(), "accessors[0]: byteOffset + count * stride exceeds bufferViews[0] (36 bytes)");
}

TEST(VenueHostile, CountNoBufferHoldsIsRefusedBeforeAllocating) {
  Tri t;
  // (2^60 + 1 - 1) * 16 = 2^64 wraps to 0: the old check passed and resize() threw.
  t.doc["bufferViews"][0]["byteStride"] = 16;
  t.doc["accessors"][0]["count"] = (uint64_t{1} << 60) + 1;
  expectRefused("count.gltf", t.text(), "accessors[0]: byteOffset + count * stride exceeds bufferViews[0]");
}

TEST(VenueHostile, BufferViewPastItsBufferIsRefused) {
  Tri t;
  t.doc["bufferViews"][2]["byteOffset"] = std::numeric_limits<uint64_t>::max() - 2;
  expectRefused("view.gltf", t.text(), "bufferViews[2]: byteOffset + byteLength exceeds buffers[0] (68 bytes)");
}

TEST(VenueHostile, IndexPastTheVerticesIsRefused) {
  Tri t;
  t.buffer[64] = 9;  // the third index
  expectRefused("index.gltf", t.text(), "index 9 past the 3 vertices");
}

TEST(VenueHostile, NonFinitePositionIsRefused) {
  Tri t;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&t.buffer[16], &nan, 4);  // the second corner's y
  expectRefused("nan.gltf", t.text(), "element 1 is not finite");
}

TEST(VenueHostile, NodesSharedWithoutEndHitTheInstanceLimit) {
  Tri t;
  // 20 levels of nodes, each with the next as 4 children: 4^20 instances from 21 nodes.
  json nodes = json::array();
  for (int i = 0; i < 20; ++i) nodes.push_back({{"children", {i + 1, i + 1, i + 1, i + 1}}});
  nodes.push_back({{"name", "leaf"}});
  t.doc["nodes"] = nodes;
  expectRefused("fan.gltf", t.text(), "node instances (the limit");
}

TEST(VenueHostile, TrianglesBeyondTheLimitAreRefused) {
  Tri t;
  json nodes = json::array();
  nodes.push_back({{"children", json::array()}});
  for (int i = 0; i < 5; ++i) {
    nodes[0]["children"].push_back(i + 1);
    nodes.push_back({{"mesh", 0}});
  }
  t.doc["nodes"] = nodes;
  const std::string text = t.text();
  auto v = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
                               "five.gltf", {}, VenueLimits{.maxTriangles = 4});
  ASSERT_FALSE(v.ok());
  EXPECT_NE(v.error().message.find("more than 4 triangles"), std::string::npos) << v.error().str();
  auto ok = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
                                "five.gltf", {}, VenueLimits{.maxTriangles = 5});
  ASSERT_TRUE(ok.ok()) << ok.error().str();
  EXPECT_EQ(ok->triangleCount(), 5u);
}

TEST(VenueHostile, MaterialIndexAtIntMaxFallsBackToTheDefault) {
  Tri t;
  t.doc["meshes"][0]["primitives"][0]["material"] = std::numeric_limits<int>::max();
  const std::string text = t.text();
  auto v = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()), "mat");
  ASSERT_TRUE(v.ok()) << v.error().str();
  EXPECT_EQ(v->primitives[0].material, 0);
}

TEST(VenueHostile, InMemoryVenueDoesNotReadFiles) {
  Tri t;
  json d = t.doc;
  d["buffers"] = {{{"byteLength", 68}, {"uri", "/etc/hostname"}}};
  const std::string text = d.dump();
  auto v = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()), "ext");
  ASSERT_FALSE(v.ok());
  EXPECT_NE(v.error().message.find("cannot read glTF"), std::string::npos) << v.error().str();
}

TEST(VenueHostile, GarbageIsAnErrorNotACrash) {
  for (std::string text : {std::string("glTF\x02\0\0\0\xff\xff\xff\xff", 12), std::string("{"), std::string("")}) {
    auto v = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()), "junk");
    EXPECT_FALSE(v.ok());
  }
}

TEST(VenueHostile, NanAndInfiniteUvsLoadAndSampleAsZero) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float uv[6] = {nan, 0.0f, 1.0f, nan, inf, -inf};
  Tri t(uv);
  const std::string text = t.text();
  auto v = loadVenueFromMemory(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()), "nanuv");
  ASSERT_TRUE(v.ok()) << v.error().str();
  ASSERT_TRUE(std::isnan(v->primitives[0].uvs[0].x));

  // 2x1 texture: left texel black, right texel white (linear, no sRGB decode).
  Texture tex;
  tex.width = 2;
  tex.height = 1;
  tex.srgb = false;
  tex.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255};
  const glm::vec4 atZero = tex.sampleLinear({0.0f, 0.0f});
  for (glm::vec2 bad : {glm::vec2(nan, 0.0f), glm::vec2(0.0f, nan), glm::vec2(inf, -inf), glm::vec2(nan, nan)}) {
    const glm::vec4 c = tex.sampleLinear(bad);
    for (int k = 0; k < 4; ++k) {
      EXPECT_TRUE(std::isfinite(c[k]));
      EXPECT_FLOAT_EQ(c[k], atZero[k]);
    }
  }
  // uv 0 lies on the left texel's edge: bilinear with wrap is half of each.
  EXPECT_NEAR(atZero.r, 0.5f, 1e-6f);
}

}  // namespace
}  // namespace haze
