// MVR export (My Virtual Rig, DIN SPEC 15801, written as version 1.6): a haze show becomes an
// .mvr archive a CAD program or console opens: GeneralSceneDescription.xml with every fixture
// (uuid, name, ids, GDTF and mode, patch, placement), focus points and groups, and the show's
// GDTF files embedded as they are. The placement is exactly the inverse of the import's
// (docs/mvr.md, "Export").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

inline constexpr int kMvrExportVerMajor = 1;
inline constexpr int kMvrExportVerMinor = 6;

// A random (version 4) uuid, lower case.
std::string makeMvrUuid();
// Gives every fixture without a uuid, or with one an earlier fixture already has (a copied
// fixture), a new one; returns how many it made. The show must then be saved for the uuids to
// stay the same at the next export.
int assignMvrUuids(Show& show);

// The MVR placement of a fixture: the inverse of the import (docs/mvr.md, "Frames and
// matrices"). Columns 0..2 are the fixture's local axes in MVR's frame, column 3 the GDTF origin
// in millimetres; pivotOffsetM is GdtfImport::pivotOffsetM (0 for other profiles).
glm::dmat4 hazeToMvrMatrix(const glm::vec3& positionM, const glm::vec3& rotationDeg, const glm::vec3& pivotOffsetM);
// "{u1,u2,u3}{v1,v2,v3}{w1,w2,w3}{o1,o2,o3}" in fixed notation (mvr.xsd's matrixtype has no exponents).
std::string formatMvrMatrix(const glm::dmat4& m);

struct MvrExportOptions {
  // The cue whose pan and tilt are the focus: fixtures it (or a cue before it in its list) aims
  // get a FocusPoint where their beam meets the floor. The import writes "MVR focus" cue 1.
  std::string focusList = "MVR focus";  // "" or a list the show lacks: no focus points
  std::string focusCue;                 // "" = the list's first cue
  bool force = false;                   // overwrite an existing file
  std::string providerVersion = "0.1";  // <GeneralSceneDescription providerVersion>
  // A show imported from an MVR (Show::mvrSource) is written over that file: its layers,
  // classes, trusses, scene objects, geometry files and unknown elements kept, its fixtures
  // updated where haze changed them. false: from the show alone.
  bool overSource = true;
};

struct MvrExport {
  std::string version;    // the MVR version written: "1.6", or the source's
  int fixtureCount = 0;
  int gdtfFiles = 0;      // embedded
  int gdtfWritten = 0;    // of those, written from native, IES or EULUMDAT profiles
  int focusPoints = 0;
  int groupObjects = 0;
  bool venueGlb = false;  // the venue written as venue.glb, a SceneObject
  int uuidsMade = 0;      // fixtures that got a new uuid (assignMvrUuids)
  // Over the source MVR:
  std::string source;     // the MVR written over ("" = from the show alone)
  int fixturesChanged = 0;  // placements haze changed (their Matrix rewritten)
  int fixturesRemoved = 0;  // fixtures of the show's types that the show no longer has
  int filesKept = 0;        // archive files carried over (geometry, textures, other GDTFs)
  std::vector<std::string> warnings;  // what the file does not carry, one line each
};

// Writes `show` as `mvrFile` (atomically). Fixtures without a uuid get one first (the show is
// changed; the caller saves it). Errors name the file; a profile that does not load is an error.
Result<MvrExport> exportMvr(Show& show, const std::filesystem::path& mvrFile, const MvrExportOptions& options = {});
// The same for a show file, as `haze export-mvr` and the GUI's File > Export MVR do it: uuids the
// show lacks are made and saved in the show first (SHOW.bak keeps its previous version), so that
// no MVR names uuids the show does not keep; then the MVR is written.
Result<MvrExport> exportMvrFromShowFile(const std::filesystem::path& showFile, const std::filesystem::path& mvrFile,
                                        const MvrExportOptions& options = {});

}  // namespace haze
