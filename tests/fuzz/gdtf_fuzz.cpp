// Fuzz harness: a .gdtf archive's bytes through loadGdtfFromMemory, then the profile's JSON.
#include <nlohmann/json.hpp>

#include "fixtures/gdtf.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptGdtf(const uint8_t* data, size_t size) {
  auto g = loadGdtfFromMemory(std::vector<uint8_t>(data, data + size), "fuzz.gdtf");
  if (!g || !g->profile) return false;
  (void)g->profile->optics(Attributes{});
  (void)profileToJson(*g->profile).dump();  // throws on names that are not UTF-8
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptGdtf)
