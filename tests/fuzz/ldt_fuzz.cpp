// Fuzz harness: EULUMDAT text through parseLdt, then lookups on what it accepted.
#include "fixtures/photometry.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptLdt(const uint8_t* data, size_t size) {
  auto d = parseLdt(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ldt");
  if (!d) return false;
  useDistribution(*d);
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptLdt)
