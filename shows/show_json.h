// The show file's JSON face: text -> Show with every structural problem collected (for loadShow
// and `haze validate`), Show -> diffable text (for saving), and the helpers both sides share.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "fixtures/core/result.h"
#include "fixtures/json_read.h"  // pointerToken, for the places show problems name
#include "shows/show.h"

namespace haze {

// Show files larger than this are refused before parsing: bounded memory on hostile input.
inline constexpr std::uintmax_t kMaxShowFileBytes = 64u * 1024u * 1024u;
// Deeper JSON nesting than this is refused (a show needs about 6 levels).
inline constexpr int kMaxShowJsonDepth = 64;

struct ShowParse {
  Show show;                    // as much as could be read; meaningful only without problems
  std::vector<Error> problems;  // every problem found, in file order
};

// Parses show JSON text. `file` names the show in errors and is stored as Show::file.
ShowParse parseShowText(std::string_view text, const std::filesystem::path& file);
// Reads a file (size-limited) into bytes; an Error when it cannot be read.
Result<std::string> readShowBytes(const std::filesystem::path& file);
// The text a save writes: the key order of docs/show-format.md, 2-space indent, short number arrays
// on one line, one fixture per block, a final newline.
std::string showToText(const Show& show);
// FNV-1a 64 and size of a file's bytes.
FileStamp stampOf(std::string_view bytes);
// A shutter as the show format writes it: "open", "closed" or {"strobe_hz", "duty"[, "mode"]}.
nlohmann::ordered_json shutterJson(const Shutter& s);
// The tidiest decimal double that rounds to f (0.8f -> 0.8, not 0.800000011920929).
double tidy(float f);

}  // namespace haze
