// Fuzz harness: a .glb or a .gltf with embedded data through loadVenueFromMemory, with no base
// folder (external URIs refused) and small limits so that accepted inputs stay fast.
#include <cmath>

#include "fuzz/harness.h"
#include "shows/scene/venue.h"

namespace haze::fuzz {

bool acceptVenue(const uint8_t* data, size_t size) {
  const VenueLimits limits{.maxVertices = 200'000, .maxTriangles = 100'000, .maxNodeVisits = 10'000};
  auto v = loadVenueFromMemory(std::span<const uint8_t>(data, size), "fuzz.gltf", {}, limits);
  if (!v) return false;
  // What the renderer and the reference would do next: texture lookups on every corner.
  for (const Primitive& p : v->primitives)
    for (size_t i = 0; i < p.uvs.size() && i < 64; ++i) {
      (void)v->albedo(p, p.uvs[i]);
      (void)v->emission(p, p.uvs[i]);
    }
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptVenue)
