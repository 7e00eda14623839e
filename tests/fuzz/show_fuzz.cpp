// Fuzz harness: show JSON text through parseShowText and the whole validation (inline profiles
// included), then the text a save would write.
#include "fuzz/harness.h"
#include "shows/show_json.h"
#include "shows/show_validate.h"

namespace haze::fuzz {

bool acceptShow(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // A folder that does not exist: file references in the show fail cleanly.
  const std::filesystem::path file = "/nonexistent/haze-fuzz/fuzz.haze.json";
  ShowParse parse = parseShowText(text, file);
  if (!parse.problems.empty()) return false;
  (void)showToText(parse.show);
  return validateShowText(text, file).empty();
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptShow)
