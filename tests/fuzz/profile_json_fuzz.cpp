// Fuzz harness: native profile JSON through profileFromJsonText, then optics and the JSON
// written back for what it accepted.
#include "fixtures/profile.h"
#include "fuzz/harness.h"

#include <nlohmann/json.hpp>

namespace haze::fuzz {

bool acceptProfileJson(const uint8_t* data, size_t size) {
  // A folder that does not exist: relative photometry and gobo paths must fail cleanly, and the
  // fuzzer must not read whatever happens to lie in the working folder.
  auto p = profileFromJsonText(std::string_view(reinterpret_cast<const char*>(data), size),
                               "/nonexistent/haze-fuzz", "fuzz.json");
  if (!p) return false;
  (void)(*p)->optics(Attributes{});
  (void)profileToJson(**p).dump();  // throws on invalid UTF-8: a name that was kept uncleaned
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptProfileJson)
