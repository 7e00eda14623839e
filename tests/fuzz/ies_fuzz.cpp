// Fuzz harness: IES LM-63 text through parseIes, then lookups on what it accepted.
#include "fixtures/photometry.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptIes(const uint8_t* data, size_t size) {
  auto d = parseIes(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ies");
  if (!d) return false;
  useDistribution(*d);
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptIes)
