// The GUI's remembered view settings (see gui_settings.h).
#include "shows/edit/gui_settings.h"

#include <cmath>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "fixtures/core/atomic_file.h"
#include "fixtures/core/text_file.h"
#include "shows/edit/recent_files.h"

namespace haze {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr const char* kQualities[] = {"draft", "default", "high"};
constexpr const char* kCells[] = {"auto", "separate", "merged"};
// Wider than any screen: a larger value is a broken file, not a width (one from a smaller
// screen than this one is clamped by the GUI instead, which knows the window).
constexpr float kMaxPanelWidthPx = 20000.0f;

}  // namespace

fs::path guiSettingsPath() {
  const fs::path recent = recentFilesPath();
  return recent.empty() ? fs::path{} : recent.parent_path() / "gui-settings.json";
}

GuiSettingsLoad parseGuiSettings(std::string_view text, const std::string& fileName) {
  GuiSettingsLoad out;
  const auto problem = [&](const std::string& place, const std::string& message) {
    if (!out.problem) out.problem = Error{fileName, place, message};
  };
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 1, column 2: ..."
    if (const auto colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
    problem(parseErrorPlace(text, e.byte), "not valid JSON (" + what + "); the view's defaults are used");
    return out;
  }
  if (!root.is_object()) {
    problem("", "expected a JSON object of settings; the view's defaults are used");
    return out;
  }
  GuiSettings& s = out.settings;
  if (const auto it = root.find("show_panel_width_px"); it != root.end() && !it->is_null()) {
    const float w = it->is_number() ? it->get<float>() : -1.0f;
    if (std::isfinite(w) && w > 0.0f && w <= kMaxPanelWidthPx) s.showPanelWidthPx = w;
    else problem("/show_panel_width_px", "expected a width in pixels (above 0, up to 20000) or null; the panel fits its tabs");
  }
  const auto flag = [&](const char* key, bool& value) {
    const auto it = root.find(key);
    if (it == root.end()) return;
    if (it->is_boolean()) value = it->get<bool>();
    else problem(std::string("/") + key, "expected true or false; the default is used");
  };
  flag("exposure_locked", s.exposureLocked);
  flag("fixture_numbers", s.fixtureNumbers);
  const auto choice = [&](const char* key, const auto& names, std::string& value) {
    const auto it = root.find(key);
    if (it == root.end()) return;
    std::string expected;  // "a", "b" or "c"
    for (size_t i = 0; i < std::size(names); ++i) {
      if (it->is_string() && it->get<std::string>() == names[i]) {
        value = names[i];
        return;
      }
      expected += (i == 0 ? "" : i + 1 == std::size(names) ? " or " : ", ") + std::string("\"") + names[i] + "\"";
    }
    problem(std::string("/") + key, "expected " + expected + "; the default is used");
  };
  choice("viewport_quality", kQualities, s.viewportQuality);
  choice("cells", kCells, s.cells);
  return out;
}

GuiSettingsLoad loadGuiSettings(const fs::path& file) {
  if (file.empty()) return {};
  std::error_code ec;
  if (!fs::exists(file, ec)) return {};  // first run: nothing remembered yet
  std::ifstream in(file, std::ios::binary);
  if (!in) return {GuiSettings{}, Error{file.string(), "", "cannot read the view settings; the defaults are used"}};
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parseGuiSettings(text, file.string());
}

std::string guiSettingsJson(const GuiSettings& s) {
  nlohmann::ordered_json j;
  j["show_panel_width_px"] = s.showPanelWidthPx ? json(*s.showPanelWidthPx) : json(nullptr);
  j["exposure_locked"] = s.exposureLocked;
  j["fixture_numbers"] = s.fixtureNumbers;
  j["viewport_quality"] = s.viewportQuality;
  j["cells"] = s.cells;
  return j.dump(2) + "\n";
}

Status saveGuiSettings(const fs::path& file, const GuiSettings& s) {
  if (file.empty()) return Error{"", "view settings", "neither XDG_CONFIG_HOME nor HOME is set"};
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  if (ec) return Error{file.parent_path().string(), "", "cannot create the folder: " + ec.message()};
  return writeFileAtomically(file, guiSettingsJson(s), false);
}

GuiSettings withChangedSettings(GuiSettings saved, const GuiSettings& before, const GuiSettings& now) {
  if (now.showPanelWidthPx != before.showPanelWidthPx) saved.showPanelWidthPx = now.showPanelWidthPx;
  if (now.exposureLocked != before.exposureLocked) saved.exposureLocked = now.exposureLocked;
  if (now.fixtureNumbers != before.fixtureNumbers) saved.fixtureNumbers = now.fixtureNumbers;
  if (now.viewportQuality != before.viewportQuality) saved.viewportQuality = now.viewportQuality;
  if (now.cells != before.cells) saved.cells = now.cells;
  return saved;
}

}  // namespace haze
