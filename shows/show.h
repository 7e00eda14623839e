// Show: the show model of docs/show-format.md (venue, atmosphere, cameras, profiles, fixtures with
// patch, cue lists), loaded from and saved to *.haze.json. No GL.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "atmosphere/density_spec.h"
#include "fixtures/attributes.h"
#include "fixtures/profile.h"
#include "fixtures/core/result.h"

namespace haze {

// A camera's exposure (docs/show-format.md): "auto" meters each image and ev is an offset from
// the metered EV; "manual" is an absolute EV (0: 50 cd/m^2 maps to 1 before the tone curve).
struct CameraExposureDef {
  bool manual = false;
  float ev = 0.0f;
  bool operator==(const CameraExposureDef&) const = default;
};

struct CameraDef {
  std::string name;
  std::optional<CameraExposureDef> exposure;  // none: the command line's or the default (auto)
  glm::vec3 position{0.0f, 2.0f, 10.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDeg = 40.0f;
  float farM = 100.0f;
};

struct AtmosphereDef {
  float scattering = 0.0f;      // sigma_s [1/m]
  float absorption = 0.0f;      // sigma_a [1/m]
  std::string phase = "hazy";   // hazy | isotropic | hg
  float g = 0.0f;               // hg asymmetry
  glm::vec3 ambient{0.0f};      // number or [r, g, b] in the file
  glm::vec3 background{0.0f};   // number or [r, g, b] in the file; 0 unless the show sets one
  // The density field D(x) (docs/shows.md, "Density"); none: D = 1 everywhere.
  std::optional<DensitySpec> density;
};

struct Patch {
  int universe = 1;  // from 1
  int address = 1;   // 1..512
};

struct FixtureDef {
  int id = 0;
  std::string name;
  std::string profile;  // key into Show::profiles
  std::string mode;
  glm::vec3 position{0.0f};
  glm::vec3 rotationDeg{0.0f};  // R = Rz * Ry * Rx
  std::optional<Patch> patch;
};

// What a cue sets for one cell of a multi-cell fixture (docs/cells.md).
struct CellValues {
  std::optional<float> intensity;
  std::optional<glm::vec3> color;
  bool operator==(const CellValues&) const = default;
};

// The attributes a cue sets for one fixture; unset ones track from earlier cues.
struct CueValues {
  std::optional<float> intensity, panDeg, tiltDeg, zoomDeg, goboRotationDeg, iris;
  std::optional<glm::vec3> color;
  std::optional<std::string> gobo;
  std::map<int, CellValues> cells;  // by cell index (0-based; the file counts from 1)
  // Beam optics beyond the gobo (docs/show-format.md).
  std::optional<float> frost, prismRotationDeg, bladeRotationDeg;
  std::optional<std::string> prism;
  std::optional<BladeInsertions> blades;
  std::optional<Shutter> shutter;
  bool operator==(const CueValues&) const = default;
};

struct Cue {
  std::string number;  // decimal string: "1", "1.5", "10"
  std::string label;
  double fadeS = 0.0;
  double delayS = 0.0;
  std::optional<double> followS;  // empty = wait for the operator
  std::string timecode;           // "hh:mm:ss:ff": `haze live --timecode` fires it then; "" = none
  std::map<int, CueValues> values;  // by fixture id
};

struct CueList {
  std::string name;
  std::vector<Cue> cues;
};

struct ProfileRef {
  std::string path;                  // relative to the show file; "" when inline
  std::optional<nlohmann::json> inlineObject;
  bool inlineWrapped = false;        // written as {"inline": {...}} rather than the bare object
};

// What a show file looked like on disk when it was loaded or last saved, so that a save can
// refuse to overwrite changes someone else made in between (shows/show_save.h).
struct FileStamp {
  std::uint64_t contentHash = 0;     // FNV-1a 64 of the file's bytes
  std::uintmax_t sizeBytes = 0;
  bool operator==(const FileStamp&) const = default;
};

// The newest show format version this haze reads and writes (docs/show-format.md).
inline constexpr int kShowFormatVersion = 1;

struct Show {
  std::filesystem::path file;        // where it was loaded from (paths inside are relative to it)
  std::optional<FileStamp> stamp;    // the file as loaded or last saved; empty for a new show
  std::string venueGltf;             // relative to the show file; "" = no venue (an empty stage)
  AtmosphereDef atmosphere;
  std::vector<CameraDef> cameras;
  std::map<std::string, ProfileRef> profiles;
  std::vector<FixtureDef> fixtures;
  std::vector<CueList> cueLists;

  const FixtureDef* findFixture(int id) const;
  const CueList* findCueList(const std::string& name) const;  // "" = the first list
  std::filesystem::path resolve(const std::string& relative) const;  // against file's folder
};

using ProfileSet = std::map<std::string, std::shared_ptr<const Profile>>;

// Reads and checks the structure of a show file (types, required keys, ranges that need no
// profile). Fails with the first problem; validateShowFile (shows/show_validate.h) lists all.
Result<Show> loadShow(const std::filesystem::path& file);
// Loads every profile the show names (files relative to the show, or inline objects).
Result<ProfileSet> loadProfiles(const Show& show);

}  // namespace haze
