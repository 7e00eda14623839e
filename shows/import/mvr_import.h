// MVR import (My Virtual Rig, DIN SPEC 15801): an .mvr archive becomes a haze show, with the
// embedded GDTF files extracted next to it (SHOW_gdtf/) and the scene's geometry written as one
// glTF venue (SHOW_venue.gltf + .bin). docs/mvr.md says how frames, matrices and patch map.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

// MVR's world is Z-up millimetres, haze's Y-up metres: haze(x, y, z) = (x, z, -y) / 1000,
// the same axis map as GDTF -> haze (docs/gdtf.md).
glm::vec3 mvrPointToHazeM(const glm::dvec3& mvrMm);
// A rotation (orthonormal, columns = the object's local axes in MVR world) as haze's
// [rx, ry, rz] in degrees with R = Rz * Ry * Rx, such that the object's local -Z (a GDTF beam)
// becomes haze's rotated -Y (docs/physics.md: the beam at pan = tilt = 0).
glm::vec3 mvrRotationToHazeDeg(const glm::dmat3& mvrRotation);
// The 4x4 placement of <Matrix>{u}{v}{w}{o}</Matrix> (u, v, w the local axes as columns, o the
// origin in mm); an Error message when the text is not 12 finite numbers of sane size.
Result<glm::dmat4> parseMvrMatrix(const std::string& text);
// "1025" (absolute, 1-based: universe 3 address 1) or "3.1"; nullopt-like universe 0 for "0"
// (unpatched). An Error message when the text is neither form or out of range.
Result<Patch> parseMvrAddress(const std::string& text);

// Warnings that say the same thing folded into one line each, for people: the same sentence
// after the place (the text after the last ">: "), with numbers and quoted names set aside,
// is one kind. Each kind is its first warning in full, then " (and N more like it)" when it
// came more than once; kinds in the order they first came. A stub GDTF repeated over a
// hundred channels becomes one line instead of a hundred.
std::vector<std::string> groupMvrWarnings(const std::vector<std::string>& warnings);

// What tells an imported fixture apart: the MVR's name attribute, <FixtureID>, <UnitNumber>,
// the profile it got (a GDTF's maker@type@revision) and its haze id.
struct MvrFixtureLabel {
  std::string name, fixtureId, unitNumber, type;
  int id = 0;
};
// One name per label, in order: the MVR name where no other fixture has it; else that name (or
// the type) with the FixtureID, else with "unit" and the UnitNumber (0 is none), else with the
// haze id; a name that still repeats gets " #" and the haze id.
std::vector<std::string> mvrFixtureNames(const std::vector<MvrFixtureLabel>& labels);
// Whether `name` is one mvrFixtureNames makes from these fields (any of its forms), so that an
// export leaves the MVR's own name in place instead of writing the composed one back.
bool isMvrComposedName(const std::string& name, const MvrFixtureLabel& label);

struct MvrImportOptions {
  bool writeVenue = true;          // build SHOW_venue.gltf from the scene's geometry
  std::size_t maxVenueTriangles = 4'000'000;  // geometry beyond this is left out (warned)
  bool force = false;              // overwrite an existing show file
  // Keep the MVR beside the show as SHOW_source.mvr (Show::mvrSource), for the export to write
  // what haze does not use back out.
  bool keepSource = true;
  // An embedded GDTF that is a stub (no wheels, every channel read past: Dimmer1..n) is replaced
  // by the fixture library's file of the same manufacturer and name (fixtures/fixture_library.h),
  // unless keepEmbedded. The library: libraryFolders(extraLibraries), cached in libraryCache.
  bool keepEmbedded = false;
  std::vector<std::filesystem::path> extraLibraries;
  std::filesystem::path libraryCache;
};

struct MvrImport {
  Show show;                        // as saved
  std::vector<std::string> warnings;  // "GeneralSceneDescription.xml line N <Fixture name=..>: ..."
  int fixtureCount = 0;
  int geometryInstances = 0;        // meshes placed in the venue
  std::size_t venueTriangles = 0;
  // One line per fixture type: the embedded GDTF kept, or matched to a library fixture (and how
  // its modes map), or why it was not matched.
  std::vector<std::string> libraryMatches;
};

// Reads `mvrFile`, writes `showFile` (atomically, shows/show_save.h), SHOW_gdtf/*.gdtf and the
// venue next to it. Errors name the MVR and the place; nothing is left half-written.
Result<MvrImport> importMvr(const std::filesystem::path& mvrFile, const std::filesystem::path& showFile,
                            const MvrImportOptions& options = {});

}  // namespace haze
