// Show look-ups and profile loading: each `profiles` entry is a file relative to the show or an
// inline object, loaded through fixtures/profile.h. Errors point at /profiles/NAME.
#include "shows/show.h"

#include <cctype>

#include <nlohmann/json.hpp>

#include "shows/show_json.h"
#include "shows/show_validate.h"

namespace haze {

const FixtureDef* Show::findFixture(int id) const {
  for (const FixtureDef& f : fixtures)
    if (f.id == id) return &f;
  return nullptr;
}

const GroupDef* Show::findGroup(const std::string& name) const {
  for (const GroupDef& g : groups)
    if (g.name == name) return &g;
  return nullptr;
}

const PaletteDef* Show::findPalette(const std::string& name) const {
  for (const PaletteDef& p : palettes)
    if (p.name == name) return &p;
  return nullptr;
}

const CueList* Show::findCueList(const std::string& name) const {
  if (name.empty()) return cueLists.empty() ? nullptr : &cueLists.front();
  for (const CueList& l : cueLists)
    if (l.name == name) return &l;
  return nullptr;
}

std::filesystem::path Show::resolve(const std::string& relative) const {
  std::filesystem::path p(relative);
  if (p.is_absolute()) return p;
  return file.parent_path() / p;
}

ProfileLoad loadProfilesAll(const Show& show) {
  ProfileLoad out;
  const std::string showFile = show.file.string();
  for (const auto& [name, ref] : show.profiles) {
    const std::string ptr = "/profiles/" + pointerToken(name);
    Result<std::shared_ptr<const Profile>> loaded = Error{};
    if (ref.inlineObject) {
      loaded = profileFromJson(*ref.inlineObject, show.file.parent_path(),
                               showFile + ":" + ptr + (ref.inlineWrapped ? "/inline" : ""));
    } else {
      std::filesystem::path path = show.resolve(ref.path);
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) {
        out.problems.push_back(Error{showFile, ptr, "profile file \"" + ref.path + "\" not found (looked for " +
                                                        std::filesystem::absolute(path, ec).lexically_normal().string() +
                                                        ")"});
        continue;
      }
      loaded = loadProfile(path);
    }
    if (!loaded) {
      out.problems.push_back(Error{showFile, ptr, "profile \"" + name + "\" cannot be loaded: " + loaded.error().str()});
      continue;
    }
    out.profiles[name] = std::move(loaded.value());
  }
  return out;
}

bool isMvrUuid(const std::string& text) {
  if (text.size() != 36) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
    if (dash != (text[i] == '-')) return false;
    if (!dash && !std::isxdigit(static_cast<unsigned char>(text[i]))) return false;
  }
  return true;
}

Result<ProfileSet> loadProfiles(const Show& show) {
  ProfileLoad load = loadProfilesAll(show);
  if (!load.problems.empty()) return load.problems.front();
  return std::move(load.profiles);
}

}  // namespace haze
