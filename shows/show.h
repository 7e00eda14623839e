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
#include "atmosphere/particle_spec.h"
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

// The sun (docs/physics.md, "The sun"): a directional light over the whole venue, entering a
// closed room only through its openings. Azimuth from north (-Z) towards east (+X), seen from
// above; elevation above the horizon (the XZ plane).
struct SunDef {
  bool enabled = true;
  float azimuthDeg = 180.0f;
  float elevationDeg = 45.0f;
  float illuminanceLux = 10000.0f;  // on a plane perpendicular to the sun's direction
  glm::vec3 color{1.0f};            // linear RGB filter
  bool operator==(const SunDef&) const = default;
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
  // "shadows": "soft" (default) | "hard": shadows softened by each lens disc, or point lights
  // (docs/physics.md, "Soft shadows"; FrameState::softShadows).
  bool softShadows = true;
  std::optional<SunDef> sun;  // none: no sun
  // Visible dust in the beams (docs/shows.md, "Particles"); none: the defaults, off.
  std::optional<ParticleSettings> particles;
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
  // The fixture's MVR uuid ("" = none yet): kept from an MVR import, made by the first MVR
  // export, so that a CAD program or console matches the fixture across exchanges.
  std::string mvrUuid;
};

// What a cue sets for one cell of a multi-cell fixture (docs/cells.md).
struct CellValues {
  std::optional<float> intensity;
  std::optional<glm::vec3> color;
  bool operator==(const CellValues&) const = default;
};

// The palettes a cue's entry for one fixture refers to, one per kind (docs/show-format.md,
// "Groups and palettes"); "" = none. Resolved when the cue plays, so a changed palette reaches
// every cue that refers to it.
struct PaletteRefs {
  std::string all, position, color, beam;
  bool empty() const { return all.empty() && position.empty() && color.empty() && beam.empty(); }
  bool operator==(const PaletteRefs&) const = default;
};

// The attributes a cue sets for one fixture; unset ones track from earlier cues.
struct CueValues {
  std::optional<float> intensity, panDeg, tiltDeg, zoomDeg, goboRotationDeg, iris;
  std::optional<glm::vec3> color;
  std::optional<std::string> gobo;
  // The second gobo wheel and continuous rotation (docs/show-format.md, "Attributes").
  std::optional<std::string> gobo2, color2;
  std::optional<float> ctoMired;  // docs/physics.md, "Colour temperature correction"
  std::optional<float> gobo2RotationDeg, goboSpinDegS, gobo2SpinDegS, prismSpinDegS;
  // The animation wheel (docs/physics.md, "Animation wheel").
  std::optional<std::string> animation;
  std::optional<float> animationRotationDeg, animationSpinDegS;
  std::map<int, CellValues> cells;  // by cell index (0-based; the file counts from 1)
  // Beam optics beyond the gobo (docs/show-format.md).
  std::optional<float> frost, prismRotationDeg, bladeRotationDeg;
  // "focus" in files: the lens's focus 0..1 (docs/physics.md, "Focus"), not aiming at a point.
  std::optional<float> gateFocus;
  std::optional<std::string> prism;
  std::optional<BladeInsertions> blades;
  std::optional<Shutter> shutter;
  PaletteRefs palettes;  // laid under the values above when the cue plays
  bool operator==(const CueValues&) const = default;
};

// A named, ordered selection of fixtures ("Spots SR"); the order is the order of a fan.
struct GroupDef {
  std::string name;
  std::vector<int> fixtures;  // fixture ids, in the group's order
  bool operator==(const GroupDef&) const = default;
};

enum class PaletteKind { Position, Color, Beam, All };

// A look many cues share: values per group (laid over one another in the order of Show::groups)
// and per fixture (laid over those). A palette holds only its kind's attributes.
struct PaletteDef {
  std::string name;
  PaletteKind kind = PaletteKind::All;
  std::map<std::string, CueValues> groups;  // by group name
  std::map<int, CueValues> fixtures;        // by fixture id
  bool operator==(const PaletteDef&) const = default;
};

// Delay and fade of one part of a cue (docs/show-format.md, "Timing"); unset ones are the cue's.
struct PartTiming {
  std::optional<double> delayS, fadeS;
  bool operator==(const PartTiming&) const = default;
};

enum class FadeCurve { Linear, SCurve };

// A fan: the k-th fixture of the group (from 0, in the group's order) starts k * delayStepS later
// and fades k * fadeStepS longer than the cue's times for it.
struct FanTiming {
  std::string group;
  double delayStepS = 0.0, fadeStepS = 0.0;
  bool operator==(const FanTiming&) const = default;
};

// Timing beyond the cue's one delay and fade: intensity up and down, position, colour and beam
// each with their own times, a fan across a group, and the curve every fade of the cue follows.
struct CueTimingDef {
  std::optional<PartTiming> up, down, position, color, beam;
  std::optional<FanTiming> fan;
  FadeCurve curve = FadeCurve::Linear;
  bool empty() const { return *this == CueTimingDef{}; }
  bool operator==(const CueTimingDef&) const = default;
};

enum class EffectShape { Sine, Circle, Square, Ramp, Random };

// A parametric effect that runs on a group while its cue is on stage (docs/show-format.md,
// "Effects"): the attribute moves by size * w(rate * t + phase), w in -1..1, where t is the time
// since GO and the k-th of the group's n fixtures has phase phaseDeg + k * spreadDeg / n.
struct EffectDef {
  EffectShape shape = EffectShape::Sine;
  std::string attribute;   // intensity, pan, tilt, zoom, iris, frost, gobo_rotation, prism_rotation; circle: position
  std::string group;
  double rateHz = 1.0;     // cycles per second; negative runs the other way
  double size = 0.0;       // in the attribute's unit (degrees for pan, tilt and circle)
  double phaseDeg = 0.0, spreadDeg = 0.0;
  std::uint32_t seed = 0;  // random: which sequence
  // attribute "color": the colours the wave runs through (w = -1 the first, +1 the last); size
  // 0..1 is how far the fixture's colour goes from the cue's towards them.
  std::vector<glm::vec3> colors;
  bool operator==(const EffectDef&) const = default;
};

// A cue's levels for one hazer of the show's density field (docs/shows.md, "Hazers in cues"):
// fractions of its output and of its fan's speed; unset ones track from the cue before.
struct HazerCueDef {
  std::optional<float> output, fan;
  bool operator==(const HazerCueDef&) const = default;
};

struct Cue {
  std::string number;  // decimal string: "1", "1.5", "10"
  std::string label;
  double fadeS = 0.0;
  double delayS = 0.0;
  std::optional<double> followS;  // empty = wait for the operator
  std::string timecode;           // "hh:mm:ss:ff": `haze live --timecode` fires it then; "" = none
  std::map<int, CueValues> values;  // by fixture id
  CueTimingDef timing;
  std::vector<EffectDef> effects;
  std::map<int, HazerCueDef> hazers;  // by hazer number, counted from 1 in atmosphere.density.hazers
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
// Version 2 added groups and palettes; a version-1 file is read as version 2 unchanged.
inline constexpr int kShowFormatVersion = 2;

inline constexpr double kMaxDefaultFadeS = 3600.0;

struct Show {
  std::filesystem::path file;        // where it was loaded from (paths inside are relative to it)
  std::optional<FileStamp> stamp;    // the file as loaded or last saved; empty for a new show
  int fileVersion = kShowFormatVersion;  // the format version the file had when read
  std::string venueGltf;             // relative to the show file; "" = no venue (an empty stage)
  // The MVR file the show was imported from, kept beside it (relative to the show file; "" =
  // none): an export writes its layers, classes, trusses, scene objects and geometry back out.
  std::string mvrSource;
  AtmosphereDef atmosphere;
  std::vector<CameraDef> cameras;
  std::map<std::string, ProfileRef> profiles;
  std::vector<FixtureDef> fixtures;
  std::vector<GroupDef> groups;
  std::vector<PaletteDef> palettes;
  std::vector<CueList> cueLists;
  // "default_fade": the fade in seconds a newly recorded cue gets (record cue, the GUI's Record).
  double defaultFadeS = 0.0;

  const FixtureDef* findFixture(int id) const;
  const GroupDef* findGroup(const std::string& name) const;
  const PaletteDef* findPalette(const std::string& name) const;
  const CueList* findCueList(const std::string& name) const;  // "" = the first list
  std::filesystem::path resolve(const std::string& relative) const;  // against file's folder
};

// "2e149740-6a41-bc43-bd59-8968781b11b9": 8-4-4-4-12 hexadecimal digits, either case (MVR's guid).
bool isMvrUuid(const std::string& text);

using ProfileSet = std::map<std::string, std::shared_ptr<const Profile>>;

// Reads and checks the structure of a show file (types, required keys, ranges that need no
// profile). Fails with the first problem; validateShowFile (shows/show_validate.h) lists all.
Result<Show> loadShow(const std::filesystem::path& file);
// Loads every profile the show names (files relative to the show, or inline objects).
Result<ProfileSet> loadProfiles(const Show& show);

}  // namespace haze
