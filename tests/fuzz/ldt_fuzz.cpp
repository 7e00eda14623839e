// Fuzz harness: EULUMDAT text through parseLdt, then lookups on what it accepted.
#include "fixtures/photometry.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptLdt(const uint8_t* data, size_t size) {
  auto d = parseLdt(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ldt");
  if (!d) return false;
  // An accepted distribution must also be safe to use: lookups walk the grid and symmetry.
  for (float t : {0.0f, 0.3f, 1.5f, 3.1f})
    for (float p : {0.0f, 1.0f, 4.0f, 6.2f}) (void)d->intensityCd(t, p);
  (void)d->peakCd();
  (void)d->maxThetaRad();
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptLdt)
