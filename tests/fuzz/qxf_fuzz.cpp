// Fuzz harness: a QLC+ fixture definition's text through qlcFixtureFromText, then the profile's
// optics and JSON (as `haze fixture info` uses them).
#include <string_view>

#include <nlohmann/json.hpp>

#include "fixtures/profile.h"
#include "fixtures/qlc_fixture.h"
#include "fuzz/harness.h"

namespace haze::fuzz {

bool acceptQxf(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto p = qlcFixtureFromText(text, "fuzz.qxf", "");
  if (!p || !*p) return false;
  (void)(*p)->optics(Attributes{});
  (void)profileToJson(**p).dump();  // throws on names that are not UTF-8
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptQxf)
