// packGlb: the glTF JSON rewritten so that every buffer view points into one buffer (the GLB's
// BIN chunk) and every image with a uri becomes a buffer view of its own, then the GLB container
// (glTF 2.0, section "Binary glTF Layout"): header, JSON chunk, BIN chunk, each 4-byte aligned.
#include "shows/import/glb_pack.h"

#include <cstring>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace haze {

namespace {

constexpr std::uint64_t kMaxBytes = 512ull << 20;

Result<std::vector<std::uint8_t>> readAll(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) return Error{file.string(), "", "cannot read " + what + " (" + ec.message() + ")"};
  if (size > kMaxBytes) return Error{file.string(), "", what + " is larger than 512 MB"};
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream in(file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    return Error{file.string(), "", "cannot read " + what};
  return bytes;
}

// "data:...;base64,XXXX" -> bytes; false when it is not base64 data.
bool decodeDataUri(const std::string& uri, std::vector<std::uint8_t>& out) {
  const auto comma = uri.find(',');
  if (uri.rfind("data:", 0) != 0 || comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos)
    return false;
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::uint32_t acc = 0;
  int bits = 0;
  for (std::size_t i = comma + 1; i < uri.size() && uri[i] != '='; ++i) {
    const int v = value(uri[i]);
    if (v < 0) return false;
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>((acc >> bits) & 0xff));
    }
  }
  return true;
}

void pad(std::vector<std::uint8_t>& bytes, std::uint8_t with) {
  while (bytes.size() % 4 != 0) bytes.push_back(with);
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

}  // namespace

Result<std::vector<std::uint8_t>> packGlb(const std::filesystem::path& gltfFile) {
  std::string ext = gltfFile.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".glb") return readAll(gltfFile, "the venue");
  auto text = readAll(gltfFile, "the venue");
  if (!text.ok()) return text.error();
  nlohmann::json gltf = nlohmann::json::parse(text->begin(), text->end(), nullptr, false);
  if (gltf.is_discarded() || !gltf.is_object()) return Error{gltfFile.string(), "", "the venue's glTF JSON does not parse"};
  const std::filesystem::path dir = gltfFile.parent_path();
  auto load = [&](const nlohmann::json& uri, const std::string& what) -> Result<std::vector<std::uint8_t>> {
    if (!uri.is_string()) return Error{gltfFile.string(), "", what + " has no uri; expected a file name or data URI"};
    std::vector<std::uint8_t> bytes;
    if (decodeDataUri(uri.get<std::string>(), bytes)) return bytes;
    return readAll(dir / uri.get<std::string>(), what);
  };

  // Each buffer's bytes placed in the BIN chunk, 4-byte aligned; buffer views follow them.
  std::vector<std::uint8_t> bin;
  std::vector<std::size_t> bufferStart;
  for (const nlohmann::json& b : gltf.value("buffers", nlohmann::json::array())) {
    auto bytes = load(b.contains("uri") ? b["uri"] : nlohmann::json(), "a buffer");
    if (!bytes.ok()) return bytes.error();
    bufferStart.push_back(bin.size());
    bin.insert(bin.end(), bytes->begin(), bytes->end());
    pad(bin, 0);
    if (bin.size() > kMaxBytes) return Error{gltfFile.string(), "", "the venue's buffers are larger than 512 MB"};
  }
  for (nlohmann::json& v : gltf["bufferViews"]) {
    const std::size_t b = v.value("buffer", 0u);
    if (b >= bufferStart.size()) return Error{gltfFile.string(), "", "a bufferView names a buffer the file does not have"};
    v["buffer"] = 0;
    v["byteOffset"] = v.value("byteOffset", std::size_t{0}) + bufferStart[b];
  }
  if (!gltf.contains("bufferViews")) gltf["bufferViews"] = nlohmann::json::array();
  for (nlohmann::json& image : gltf["images"]) {
    if (!image.contains("uri")) continue;
    const std::string uri = image["uri"].get<std::string>();
    auto bytes = load(image["uri"], "an image");
    if (!bytes.ok()) return bytes.error();
    std::string lowerUri = uri;
    for (char& c : lowerUri) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool jpeg = lowerUri.find(".jpg") != std::string::npos || lowerUri.find(".jpeg") != std::string::npos ||
                      lowerUri.rfind("data:image/jpeg", 0) == 0;
    gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes->size()}});
    image.erase("uri");
    image["bufferView"] = gltf["bufferViews"].size() - 1;
    image["mimeType"] = jpeg ? "image/jpeg" : "image/png";
    bin.insert(bin.end(), bytes->begin(), bytes->end());
    pad(bin, 0);
    if (bin.size() > kMaxBytes) return Error{gltfFile.string(), "", "the venue with its images is larger than 512 MB"};
  }
  if (gltf["images"].is_null()) gltf.erase("images");
  if (gltf["bufferViews"].empty()) gltf.erase("bufferViews");
  if (!bin.empty()) gltf["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
  else gltf.erase("buffers");

  std::string json = gltf.dump();
  std::vector<std::uint8_t> jsonChunk(json.begin(), json.end());
  pad(jsonChunk, ' ');
  std::vector<std::uint8_t> out;
  const std::size_t total = 12 + 8 + jsonChunk.size() + (bin.empty() ? 0 : 8 + bin.size());
  putU32(out, 0x46546C67);  // "glTF"
  putU32(out, 2);
  putU32(out, static_cast<std::uint32_t>(total));
  putU32(out, static_cast<std::uint32_t>(jsonChunk.size()));
  putU32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), jsonChunk.begin(), jsonChunk.end());
  if (!bin.empty()) {
    putU32(out, static_cast<std::uint32_t>(bin.size()));
    putU32(out, 0x004E4942);  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

}  // namespace haze
