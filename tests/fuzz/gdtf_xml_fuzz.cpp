// Fuzz harness: the bytes as a GDTF's description.xml, zipped in memory with a small gobo
// image, through loadGdtfFromMemory. Mutating a whole .gdtf (fuzz_gdtf) mostly breaks the zip's
// checksums; this one reaches the XML, geometry, wheel and DMX readers directly.
#include <cstdlib>
#include <cstring>
#include <vector>

#include <nlohmann/json.hpp>
#include <zip.h>

#include "fixtures/gdtf.h"
#include "fuzz/harness.h"

namespace haze::fuzz {
namespace {

// A 2x2 grey+alpha PNG, the wheel image the seeds' MediaFileName="dots" names.
const unsigned char kPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x04, 0x00, 0x00, 0x00, 0xd8, 0xbf, 0xc5, 0xaf, 0x00, 0x00, 0x00,
    0x10, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xff, 0x9f, 0x01, 0x04, 0x1b, 0xfe, 0x03, 0x00, 0x1c,
    0xee, 0x05, 0x7c, 0x99, 0xde, 0x6c, 0x65, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60,
    0x82};

// A stored (uncompressed) zip of description.xml and wheels/dots.png, built with libzip.
std::vector<uint8_t> zipDescription(const uint8_t* xml, size_t size) {
  std::vector<uint8_t> out;
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* mem = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!mem) return out;
  zip_source_keep(mem);  // kept past zip_close to read the archive back
  zip_t* z = zip_open_from_source(mem, ZIP_TRUNCATE, &error);
  if (!z) {
    zip_source_free(mem);
    return out;
  }
  auto add = [&](const char* name, const void* data, size_t n) {
    zip_source_t* s = zip_source_buffer(z, data, n, 0);
    if (s && zip_file_add(z, name, s, ZIP_FL_OVERWRITE) < 0) zip_source_free(s);
  };
  add("description.xml", size ? xml : reinterpret_cast<const uint8_t*>(""), size);
  add("wheels/dots.png", kPng, sizeof kPng);
  if (zip_close(z) == 0 && zip_source_open(mem) == 0) {
    zip_source_seek(mem, 0, SEEK_END);
    const zip_int64_t n = zip_source_tell(mem);
    zip_source_seek(mem, 0, SEEK_SET);
    if (n > 0) {
      out.resize(static_cast<size_t>(n));
      if (zip_source_read(mem, out.data(), static_cast<zip_uint64_t>(n)) != n) out.clear();
    }
    zip_source_close(mem);
  } else if (z) {
    zip_discard(z);
  }
  zip_source_free(mem);
  return out;
}

}  // namespace

bool acceptGdtfXml(const uint8_t* data, size_t size) {
  std::vector<uint8_t> archive = zipDescription(data, size);
  if (archive.empty()) return false;
  auto g = loadGdtfFromMemory(std::move(archive), "fuzz.gdtf");
  if (!g || !g->profile) return false;
  (void)g->profile->optics(Attributes{});
  (void)profileToJson(*g->profile).dump();  // throws on names that are not UTF-8
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptGdtfXml)
