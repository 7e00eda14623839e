// sheetChanges (see sheet_changes.h).
#include "app/sheet_changes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "shows/id_ranges.h"

namespace haze {

namespace {

// The state keys each palette kind covers (docs/show-format.md, "Groups and palettes").
bool coveredBy(const std::string& kind, const std::string& key) {
  if (kind == "all") return key != "intensity";
  const bool position = key == "pan" || key == "tilt";
  const bool color = key == "color" || key == "color2" || key == "cto";
  if (kind == "position") return position;
  if (kind == "color") return color;
  return !position && !color && key != "intensity";  // beam
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", std::abs(v) < 5e-4 ? 0.0 : v);
  return text;
}

std::string percent(double v) {
  char text[32];
  const double p = v * 100.0;
  std::snprintf(text, sizeof text, std::abs(p - std::round(p)) < 0.05 ? "%.0f %%" : "%.1f %%", p);
  return text;
}

std::string shown(const std::string& key, const nlohmann::ordered_json& value) {
  if (key == "intensity" && value.is_number()) return "@ " + percent(value.get<double>());
  if (key == "color" && value.is_array() && value.size() == 3)
    return "color " + srgbCode(value[0].get<float>(), value[1].get<float>(), value[2].get<float>());
  if (value.is_string()) return key + " " + value.get<std::string>();
  if (value.is_number()) return key + " " + number(value.get<double>());
  if (value.is_array()) {
    std::string parts;
    for (const auto& v : value) parts += (parts.empty() ? "" : " ") + (v.is_number() ? number(v.get<double>()) : v.dump());
    return key + " [" + parts + "]";
  }
  if (value.is_object() && value.contains("strobe_hz")) return key + " strobe " + number(value["strobe_hz"].get<double>()) + " Hz";
  return key + " " + value.dump();
}

float toSrgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace

std::string srgbCode(float r, float g, float b) {
  char text[16];
  auto byte = [](float v) { return static_cast<int>(std::lround(toSrgb(v) * 255.0f)); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(r), byte(g), byte(b));
  return text;
}

std::vector<std::string> sheetChanges(const Show& show, const ProfileSet& profiles, const Cue& cue,
                                      const nlohmann::ordered_json& before, const nlohmann::ordered_json& after) {
  // (type, change) -> fixture ids; the first id orders the lines.
  std::map<std::pair<std::string, std::string>, std::vector<int>> runs;
  for (const auto& [idText, now] : after.items()) {
    const int id = std::stoi(idText);
    const auto was = before.find(idText);
    std::vector<std::string> keys;
    for (const auto& [key, value] : now.items())
      if (was == before.end() || !was->contains(key) || (*was)[key] != value) keys.push_back(key);
    if (keys.empty()) continue;
    // The palettes this cue lays on the fixture, kind -> name, and the keys they account for.
    std::vector<std::pair<std::string, std::string>> palettes;
    if (auto v = cue.values.find(id); v != cue.values.end()) {
      const PaletteRefs& r = v->second.palettes;
      for (const auto& [kind, name] : {std::pair<std::string, std::string>{"all", r.all}, {"position", r.position},
                                       {"color", r.color}, {"beam", r.beam}})
        if (!name.empty()) palettes.push_back({kind, name});
    }
    std::string change;
    const auto add = [&change](const std::string& part) { change += (change.empty() ? "" : ", ") + part; };
    if (std::find(keys.begin(), keys.end(), "intensity") != keys.end()) add(shown("intensity", now["intensity"]));
    std::set<std::string> named;
    for (const auto& [kind, name] : palettes)
      if (std::any_of(keys.begin(), keys.end(), [&](const std::string& k) { return coveredBy(kind, k); }) &&
          named.insert(name).second)
        add("palette " + name);
    for (const std::string& key : keys) {
      if (key == "intensity") continue;
      if (std::any_of(palettes.begin(), palettes.end(), [&](const auto& p) { return coveredBy(p.first, key); })) continue;
      add(shown(key, now[key]));
    }
    const FixtureDef* f = show.findFixture(id);
    std::string type = f ? f->profile : "";
    if (f)
      if (auto p = profiles.find(f->profile); p != profiles.end() && p->second && !p->second->name.empty())
        type = p->second->name;
    runs[{type, change}].push_back(id);
  }
  std::vector<std::pair<int, std::string>> lines;
  for (const auto& [key, ids] : runs)
    lines.push_back({*std::min_element(ids.begin(), ids.end()),
                     idRanges(ids) + (key.first.empty() ? "" : " " + key.first) + " " + key.second});
  std::sort(lines.begin(), lines.end());
  std::vector<std::string> out;
  for (auto& [first, line] : lines) out.push_back(std::move(line));
  return out;
}

}  // namespace haze
