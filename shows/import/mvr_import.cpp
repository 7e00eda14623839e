// MVR -> haze show: walks GeneralSceneDescription.xml (layers, group objects, scene objects,
// trusses, fixtures, focus points, symbols), composes the matrices down the tree, imports each
// fixture's embedded GDTF once, and writes the show, its GDTF folder and its venue.
#include "shows/import/mvr_import.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <pugixml.hpp>

#include "fixtures/fixture_library.h"
#include "fixtures/gdtf.h"
#include "fixtures/gdtf_dmx.h"
#include "fixtures/core/zip_archive.h"
#include "fixtures/core/text_file.h"
#include "shows/import/mvr_camera.h"
#include "shows/import/mvr_venue.h"
#include "shows/focus.h"
#include "shows/show_save.h"

namespace haze {

namespace {

constexpr const char* kSceneXml = "GeneralSceneDescription.xml";
constexpr const char* kUnnamedGroup = "\x01unnamed ";  // no MVR name starts with a control character
constexpr int kMaxDepth = 32;  // nesting of groups and symbols; bounds a symbol that names itself
// Placements of geometry in all: symbols of symbols multiply, so a small hostile file could ask
// for 10^30 of them; real rigs have a few thousand.
constexpr std::size_t kMaxGeometryInstances = 200000;

struct FixtureSource {
  std::string spec, mode, name, fixtureId, unitNumber, address, focus, place, uuid;
  std::vector<std::string> groups;  // the GroupObjects around it, outermost first (haze groups)
  glm::dmat4 worldMm{1.0};
  int extraAddresses = 0;
};

struct GdtfEntry {
  bool ok = false;
  std::string file;           // archive entry
  std::string profileKey;     // key in Show::profiles
  std::vector<std::string> modes;
  glm::vec3 pivotOffsetM{0.0f};
  std::shared_ptr<const Profile> profile;  // for aiming: lens offset, pan and tilt ranges
  std::map<std::string, std::string> modeOf;  // a library match: embedded mode -> the library's
};

// A GDTF that says nothing haze can draw beyond a default beam: no wheels, and every channel of
// every mode read past or one of the numbered dimmers Capture's stubs name every slot with
// (Dimmer1..n, read as the fixture's dimmers: fixtures/gdtf_dmx.cpp).
bool isStubGdtf(const Profile& p) {
  if (!p.goboWheels.empty() || !p.colorWheels.empty() || !p.prisms.empty()) return false;
  for (const DmxMode& m : p.modes)
    for (const DmxChannel& c : m.channels)
      if (c.attribute != DmxAttribute::None && !(c.attribute == DmxAttribute::Intensity && numberedDimmer(c.name) > 0))
        return false;
  return true;
}

class SceneWalker {
 public:
  SceneWalker(const std::string& text, std::vector<std::string>& warnings) : warnings_(warnings) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }

  std::string place(const pugi::xml_node& n) const {
    const auto offset = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, n.offset_debug()));
    const std::size_t line = 1 + static_cast<std::size_t>(std::lower_bound(newlines_.begin(), newlines_.end(), offset) - newlines_.begin());
    std::string s = std::string(kSceneXml) + " line " + std::to_string(line) + " <" + n.name();
    if (const char* nm = n.attribute("name").value(); *nm) s += std::string(" name=\"") + nm + "\"";
    return s + ">";
  }
  void warn(const pugi::xml_node& n, const std::string& message) { warnings_.push_back(place(n) + ": " + message); }
  void warnOnce(const std::string& key, const pugi::xml_node& n, const std::string& message) {
    if (warned_.insert(key).second) warn(n, message);
  }

  glm::dmat4 localMatrix(const pugi::xml_node& n) {
    pugi::xml_node m = n.child("Matrix");
    if (!m) return glm::dmat4(1.0);
    auto parsed = parseMvrMatrix(m.text().as_string());
    if (!parsed.ok()) {
      warn(m, parsed.error().message + "; the identity is used");
      return glm::dmat4(1.0);
    }
    return *parsed;
  }

  void walkScene(const pugi::xml_node& scene) {
    for (pugi::xml_node s : scene.child("AUXData").children("Symdef"))
      symdefs_[lower(s.attribute("uuid").value())] = s;
    pugi::xml_node layers = scene.child("Layers");
    for (pugi::xml_node layer : layers.children()) {
      if (std::string(layer.name()) != "Layer") {
        warnOnce(std::string("layers/") + layer.name(), layer, "unknown element in <Layers>; ignored");
        continue;
      }
      walkChildren(layer.child("ChildList"), localMatrix(layer), 0);
    }
  }

  std::vector<FixtureSource> fixtures;
  std::vector<std::string> groupNames;  // every GroupObject's name, in the order of the file
  std::vector<MvrGeometryInstance> geometry;
  std::map<std::string, glm::dvec3> focusPointsMm;  // uuid (lower case) -> world position

 private:
  static std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }

  void walkChildren(const pugi::xml_node& list, const glm::dmat4& parent, int depth) {
    if (!list) return;
    if (depth > kMaxDepth) {
      warn(list, "nesting deeper than " + std::to_string(kMaxDepth) + " levels; the rest is left out");
      return;
    }
    for (pugi::xml_node obj : list.children()) {
      if (obj.type() != pugi::node_element) continue;
      const std::string kind = obj.name();
      const glm::dmat4 world = parent * localMatrix(obj);
      if (kind == "GroupObject") {
        // A group becomes a haze group of the fixtures inside it (an export writes each show
        // group as one); equal names share one group; unnamed ones get a key of their own here
        // and a number once it is known which hold fixtures (addGroups).
        std::string name = obj.attribute("name").value();
        if (name.empty()) name = std::string(kUnnamedGroup) + std::to_string(groupNames.size());
        if (std::find(groupNames.begin(), groupNames.end(), name) == groupNames.end()) groupNames.push_back(name);
        groupStack_.push_back(name);
        walkChildren(obj.child("ChildList"), world, depth + 1);
        groupStack_.pop_back();
      } else if (kind == "Fixture") {
        addFixture(obj, world);
        walkChildren(obj.child("ChildList"), world, depth + 1);
      } else if (kind == "SceneObject" || kind == "Truss" || kind == "Support" || kind == "VideoScreen" ||
                 kind == "Projector" || kind == "FocusPoint") {
        if (kind == "FocusPoint") {
          focusPointsMm[lower(obj.attribute("uuid").value())] = glm::dvec3(world[3]);
          // Its geometry is the marker a drawing shows, not a thing in the room: Vectorworks
          // puts a 0.46 m square at each focus point, right in the middle of the beam aimed at
          // it, where it would cast a shadow on the floor.
          if (obj.child("Geometries").first_child())
            warn(obj, "the focus point's geometry (a marker for drawings) is not placed in the venue; it would shadow the beam aimed at it");
        } else {
          if (!obj.child("GDTFSpec").text().empty())
            warnOnce("gdtf-" + kind, obj, "a " + kind + " with a GDTFSpec is imported as geometry only, not as a fixture");
          addGeometries(obj.child("Geometries"), world, depth + 1, "");
        }
        walkChildren(obj.child("ChildList"), world, depth + 1);
      } else {
        warnOnce("object/" + kind, obj, "unknown scene element <" + kind + ">; ignored");
      }
    }
  }

  // symbolPlace: the outermost <Symbol> that led here, so each placement is named by its own
  // place rather than by the shared Symdef's.
  void addGeometries(const pugi::xml_node& list, const glm::dmat4& parent, int depth, const std::string& symbolPlace) {
    if (!list) return;
    if (depth > kMaxDepth) {
      warn(list, "symbols nested deeper than " + std::to_string(kMaxDepth) + " levels (a symbol using itself?); left out");
      return;
    }
    for (pugi::xml_node g : list.children()) {
      if (g.type() != pugi::node_element) continue;
      const std::string kind = g.name();
      const glm::dmat4 world = parent * localMatrix(g);
      if (geometry.size() >= kMaxGeometryInstances) {
        warnOnce("instances", g, "more than " + std::to_string(kMaxGeometryInstances) + " geometry placements; the rest is left out");
        return;
      }
      if (kind == "Geometry3D") {
        const std::string file = g.attribute("fileName").value();
        if (file.empty()) {
          warn(g, "Geometry3D without fileName; ignored");
          continue;
        }
        geometry.push_back({file, world, symbolPlace.empty() ? place(g) : symbolPlace});
      } else if (kind == "Symbol") {
        auto it = symdefs_.find(lower(g.attribute("symdef").value()));
        if (it == symdefs_.end()) {
          warn(g, std::string("Symbol names symdef \"") + g.attribute("symdef").value() + "\", which <AUXData> does not define; ignored");
          continue;
        }
        addGeometries(it->second.child("ChildList"), world, depth + 1, symbolPlace.empty() ? place(g) : symbolPlace);
      } else {
        warnOnce("geometry/" + kind, g, "unknown geometry element <" + kind + ">; ignored");
      }
    }
  }

  void addFixture(const pugi::xml_node& obj, const glm::dmat4& world) {
    FixtureSource f;
    f.groups = groupStack_;
    f.place = place(obj);
    f.worldMm = world;
    f.name = obj.attribute("name").value();
    f.uuid = obj.attribute("uuid").value();
    f.spec = obj.child("GDTFSpec").text().as_string();
    f.mode = obj.child("GDTFMode").text().as_string();
    f.fixtureId = obj.child("FixtureID").text().as_string();
    f.unitNumber = obj.child("UnitNumber").text().as_string();
    f.focus = lower(obj.child("Focus").text().as_string());
    pugi::xml_node first;
    for (pugi::xml_node a : obj.child("Addresses").children("Address")) {
      if (!first) first = a;
      else ++f.extraAddresses;
      if (a.attribute("break").as_int(0) == 0 && first != a && f.address.empty()) first = a;
    }
    if (first) f.address = first.text().as_string();
    if (f.extraAddresses > 0)
      warnOnce("breaks", obj, "further DMX breaks (<Address break=\"N\">) are not imported; the first address is used");
    static const std::set<std::string> known = {"Matrix", "GDTFSpec", "GDTFMode", "FixtureID", "Focus", "Addresses",
                                                "ChildList", "Geometries", "UnitNumber", "FixtureTypeId", "CustomId",
                                                "Classing", "Mappings"};
    for (pugi::xml_node c : obj.children()) {
      if (c.type() != pugi::node_element || known.count(c.name())) continue;
      std::string what = std::string("<") + c.name() + "> of fixtures is not used by haze; ignored";
      if (std::string(c.name()) == "Color") what = "<Color> (the fixture's colour in drawings) is not a light colour in haze; ignored";
      if (std::string(c.name()) == "CastShadow") what = "<CastShadow> is not imported: every haze fixture casts shadows; ignored";
      warnOnce(std::string("fixture/") + c.name(), c, what);
    }
    fixtures.push_back(std::move(f));
  }

  std::vector<std::size_t> newlines_;  // offsets of '\n' in the XML, for line numbers
  std::vector<std::string>& warnings_;
  std::set<std::string> warned_;
  std::vector<std::string> groupStack_;  // the GroupObjects the walk is inside
  std::map<std::string, pugi::xml_node> symdefs_;
};

std::string lowerAscii(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "SHOW.haze.json" -> "SHOW"
std::string showStem(const std::filesystem::path& file) {
  std::string name = file.filename().string();
  for (const char* ext : {".haze.json", ".json"})
    if (name.size() > std::strlen(ext) && name.compare(name.size() - std::strlen(ext), std::string::npos, ext) == 0)
      return name.substr(0, name.size() - std::strlen(ext));
  return name;
}

std::string safeFileName(std::string s) {
  for (char& c : s)
    if (c == '/' || c == '\\' || c == ':' || static_cast<unsigned char>(c) < 32) c = '_';
  return s;
}

// The archive entry a GDTFSpec names: as written, or with ".gdtf" added (Vectorworks leaves it off).
std::string findGdtfEntry(const ZipArchive& zip, const std::string& spec) {
  if (spec.empty()) return "";
  if (zip.contains(spec)) {
    for (const ZipEntry& e : zip.entries())
      if (e.name == spec) return spec;
    for (const ZipEntry& e : zip.entries()) {
      std::string a = e.name, b = spec;
      std::transform(a.begin(), a.end(), a.begin(), [](unsigned char c) { return std::tolower(c); });
      std::transform(b.begin(), b.end(), b.begin(), [](unsigned char c) { return std::tolower(c); });
      if (a == b) return e.name;
    }
  }
  if (spec.size() < 5 || spec.substr(spec.size() - 5) != ".gdtf") return findGdtfEntry(zip, spec + ".gdtf");
  return "";
}

// One import run: the archive, where the show goes, and what earlier stages found. Each stage
// is a method, called in order by importMvr.
class MvrImporter {
 public:
  MvrImporter(const ZipArchive& zip, std::string src, const std::filesystem::path& showFile, SceneWalker& walker, MvrImport& out,
              const MvrImportOptions& options)
      : zip_(zip), src_(std::move(src)), walker_(walker), out_(out), options_(options) {
    showDir_ = showFile.parent_path().empty() ? std::filesystem::path(".") : showFile.parent_path();
    stem_ = showStem(showFile);
    gdtfDirName_ = stem_ + "_gdtf";
    std::error_code ec;
    std::filesystem::create_directories(showDir_, ec);
    for (const FixtureSource& f : walker_.fixtures) {
      if (!f.fixtureId.empty()) {
        char* end = nullptr;
        const long v = std::strtol(f.fixtureId.c_str(), &end, 10);
        if (*end == '\0' && v > 0 && v < 1000000000) takenIds_.insert(static_cast<int>(v));
      }
    }
    nextId_ = takenIds_.empty() ? 1 : *takenIds_.rbegin() + 1;
  }

  // Every fixture whose GDTF imports, placed; one GDTF import per GDTFSpec.
  Status addFixtures() {
    for (const FixtureSource& f : walker_.fixtures) {
      auto [it, fresh] = gdtfs_.try_emplace(f.spec);
      GdtfEntry& g = it->second;
      if (fresh)
        if (Status s = importGdtf(f, g); !s.ok()) return s;
      if (g.ok) addFixture(f, g);
    }
    const std::vector<std::string> names = mvrFixtureNames(labels_);
    for (std::size_t i = 0; i < names.size(); ++i) out_.show.fixtures[i].name = names[i];
    out_.fixtureCount = static_cast<int>(out_.show.fixtures.size());
    addGroups();
    return Ok{};
  }

  // The GroupObjects as haze groups, in the file's order, with the fixtures that imported (a
  // group left empty by fixtures that did not is left out); unnamed ones become "MVR group N".
  void addGroups() {
    int unnamed = 0;
    for (const std::string& name : walker_.groupNames) {
      GroupDef g;
      g.name = name;
      for (const auto& [id, groups] : fixtureGroups_)
        if (std::find(groups.begin(), groups.end(), name) != groups.end()) g.fixtures.push_back(id);
      if (g.fixtures.empty()) continue;
      if (name.rfind(kUnnamedGroup, 0) == 0) g.name = "MVR group " + std::to_string(++unnamed);
      out_.show.groups.push_back(std::move(g));
    }
  }

  // Focus: one cue that aims each fixture at its focus point (pan/tilt within the profile's
  // range). Every fixture at full, as at a focus call, so rendering the imported show shows the rig.
  void addFocusCue() {
    Cue focusCue;
    focusCue.number = "1";
    focusCue.label = "Focus from MVR";
    for (const FixtureDef& def : out_.show.fixtures) focusCue.values[def.id].intensity = 1.0f;
    for (const auto& [index, uuid] : focusOf_) {
      const FixtureDef& def = out_.show.fixtures[index];
      auto fp = walker_.focusPointsMm.find(uuid);
      if (fp == walker_.focusPointsMm.end()) {
        out_.warnings.push_back("fixture " + std::to_string(def.id) + " \"" + def.name + "\": its Focus names no <FocusPoint>; not aimed");
        continue;
      }
      const glm::vec3 pointM = mvrPointToHazeM(fp->second);
      if (glm::length(pointM - def.position) < 1e-3f) continue;
      const GdtfEntry* g = nullptr;
      for (const auto& [spec, e] : gdtfs_)
        if (e.ok && e.profileKey == def.profile) g = &e;
      if (g == nullptr || !g->profile) continue;
      // The same solver as the GUI's focus: the lens offset turns with the head, and of the
      // equivalent answers the one inside the profile's ranges nearest pan 0, tilt 0 wins.
      const FocusResult aim = focusOnPoint(def, *g->profile, pointM, 0.0f, 0.0f);
      if (!aim.reached) {
        out_.warnings.push_back("fixture " + std::to_string(def.id) + " \"" + def.name + "\": its focus point is out of reach (" +
                                aim.note + "); not aimed");
        continue;
      }
      auto tidyDeg = [](float deg) { return std::round(deg * 100.0f) / 100.0f; };
      const float pan = tidyDeg(aim.panDeg), tilt = tidyDeg(aim.tiltDeg);
      CueValues& values = focusCue.values[def.id];
      values.panDeg = pan;
      values.tiltDeg = tilt;
    }
    if (!focusCue.values.empty()) out_.show.cueLists.push_back(CueList{"MVR focus", {focusCue}});
  }

  Status writeVenue(std::size_t maxVenueTriangles) {
    const std::string venueName = stem_ + "_venue.gltf";
    Result<MvrVenueStats> venue = MvrVenueStats{};
    if (!walker_.geometry.empty()) venue = writeMvrVenue(zip_, walker_.geometry, showDir_ / venueName, maxVenueTriangles, out_.warnings);
    if (!venue.ok()) return venue.error();
    if (venue->instances == 0 && !out_.show.fixtures.empty()) {
      // Nothing to stand on: a floor at MVR z = 0 under the rig and 10 m around it.
      glm::vec2 lo(1e30f), hi(-1e30f);
      for (const FixtureDef& def : out_.show.fixtures) {
        lo = glm::min(lo, glm::vec2(def.position.x, def.position.z));
        hi = glm::max(hi, glm::vec2(def.position.x, def.position.z));
      }
      lo = glm::round(lo - 10.0f);
      hi = glm::round(hi + 10.0f);
      out_.warnings.push_back(std::string(kSceneXml) + " <Scene>: the MVR places no geometry; the venue is a floor at MVR z = 0 from (" +
                              std::to_string(static_cast<int>(lo.x)) + ", " + std::to_string(static_cast<int>(-hi.y)) + ") to (" +
                              std::to_string(static_cast<int>(hi.x)) + ", " + std::to_string(static_cast<int>(-lo.y)) +
                              ") m (MVR x, y), so that beams have somewhere to land");
      venue = writeMvrFloorVenue(showDir_ / venueName, lo, hi);
      if (!venue.ok()) return venue.error();
    }
    out_.geometryInstances = venue->instances;
    out_.venueTriangles = venue->triangles;
    if (venue->instances > 0) out_.show.venueGltf = venueName;
    venueTrianglesM_ = std::move(venue->placedTrianglesM);
    return Ok{};
  }

  // A camera that sees the rig and where it is aimed (its focus points, else where its beams at
  // rest meet the venue, if within 30 m), from inside the venue when walls enclose it.
  void addOverviewCamera() {
    if (out_.show.fixtures.empty()) return;
    std::vector<glm::vec3> rigPointsM;
    std::vector<bool> focused(out_.show.fixtures.size(), false);
    for (const FixtureDef& def : out_.show.fixtures) rigPointsM.push_back(def.position);
    const Venue rayVenue = venueFromTriangles(std::move(venueTrianglesM_));
    const Bvh venue(rayVenue);
    for (const auto& [index, uuid] : focusOf_) {
      if (auto fp = walker_.focusPointsMm.find(uuid); fp != walker_.focusPointsMm.end()) {
        const glm::vec3 focusM = mvrPointToHazeM(fp->second);
        rigPointsM.push_back(focusM);
        focused[index] = true;
        // A focus point is often in the air (Vectorworks puts them at head height); the pool
        // of light is where the beam through it lands, so that belongs in the picture too.
        const glm::vec3 along = focusM - out_.show.fixtures[index].position;
        if (glm::length(along) < 1e-3f) continue;
        const glm::vec3 dir = glm::normalize(along);
        const float hit = firstHitM(venue, focusM, dir, 30.0f);
        if (hit > 0.0f) rigPointsM.push_back(focusM + hit * dir);
      }
    }
    for (std::size_t i = 0; i < out_.show.fixtures.size(); ++i) {
      if (focused[i]) continue;
      const float hit = firstHitM(venue, out_.show.fixtures[i].position, beamDirs_[i], 30.0f);
      if (hit > 0.0f) rigPointsM.push_back(out_.show.fixtures[i].position + hit * beamDirs_[i]);
    }
    out_.show.cameras.push_back(mvrOverviewCamera(rigPointsM, venue));
  }

 private:
  // Reads the GDTF that `f` names into `g` (g.ok when it imported) and writes its bytes next to
  // the show for the profile. Only a failure to write is an error; a GDTF that does not import
  // is a warning and its fixtures are left out.
  Status importGdtf(const FixtureSource& f, GdtfEntry& g) {
    g.file = findGdtfEntry(zip_, f.spec);
    if (f.spec.empty()) {
      out_.warnings.push_back(f.place + ": fixture has no <GDTFSpec>; fixtures without a GDTF are left out");
    } else if (g.file.empty()) {
      out_.warnings.push_back(f.place + ": GDTFSpec \"" + f.spec + "\" is not in the archive; fixtures of this type are left out");
    } else if (auto bytes = zip_.read(g.file); !bytes.ok()) {
      out_.warnings.push_back(f.place + ": " + bytes.error().str() + "; fixtures of this type are left out");
    } else {
      std::vector<std::uint8_t> copy = *bytes;
      auto imported = loadGdtfFromMemory(std::move(copy), src_ + ":" + g.file);
      if (!imported.ok()) {
        out_.warnings.push_back(f.place + ": its GDTF does not import (" + imported.error().str() +
                                "); fixtures of this type are left out");
      } else {
        std::string base = safeFileName(g.file);
        std::string key = base.size() > 5 && base.substr(base.size() - 5) == ".gdtf" ? base.substr(0, base.size() - 5) : base;
        while (usedKeys_.count(key)) key += "_";
        usedKeys_.insert(key);
        g.profileKey = key;
        const std::string rel = gdtfDirName_ + "/" + key + ".gdtf";
        std::error_code ec;
        std::filesystem::create_directories(showDir_ / gdtfDirName_, ec);
        Status w =
            writeFileAtomically(showDir_ / rel, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()), false);
        if (!w.ok()) return w.error();
        out_.show.profiles[key] = ProfileRef{rel, std::nullopt, false};
        for (const auto& m : imported->profile->modes) g.modes.push_back(m.name);
        g.pivotOffsetM = imported->pivotOffsetM;
        g.profile = imported->profile;
        for (const std::string& w2 : imported->warnings) out_.warnings.push_back(g.file + ": " + w2);
        g.ok = true;
        matchLibrary(g, *imported->profile);
      }
    }
    return Ok{};
  }

  // Replaces a stub GDTF by the library's fixture of the same manufacturer and name: its profile
  // for the show and for aiming, each embedded mode mapped to a library mode of the same footprint
  // (else the first). One line in out_.libraryMatches either way.
  void matchLibrary(GdtfEntry& g, const Profile& embedded) {
    const std::string what = g.file + " (" + embedded.manufacturer + " " + embedded.name + ")";
    if (options_.keepEmbedded) {
      out_.libraryMatches.push_back(what + ": kept as embedded (--keep-embedded)");
      return;
    }
    if (!isStubGdtf(embedded)) {
      out_.libraryMatches.push_back(what + ": kept (the embedded GDTF has channels haze drives)");
      return;
    }
    if (!library_) library_ = indexLibrary(libraryFolders(options_.extraLibraries), options_.libraryCache);
    const std::string wanted = compactText(embedded.manufacturer + embedded.name);
    const LibraryEntry* hit = nullptr;
    for (const LibraryEntry* e : searchLibrary(*library_, embedded.manufacturer + " " + embedded.name))
      if (compactText(e->title()).rfind(wanted, 0) == 0) {
        hit = e;
        break;
      }
    if (!hit) {
      out_.libraryMatches.push_back(what + ": a stub (no wheels, its channels Dimmer1..n), and no library fixture is named \"" +
                                    embedded.manufacturer + " " + embedded.name + "\" (" + std::to_string(library_->entries.size()) +
                                    " files indexed); kept");
      return;
    }
    auto profile = loadProfile(hit->file);
    if (!profile) {
      out_.libraryMatches.push_back(what + ": a stub; the library's " + hit->file + " does not load (" + profile.error().str() + "); kept");
      return;
    }
    std::string modes;
    for (const DmxMode& m : embedded.modes) {
      const DmxMode* same = nullptr;
      for (const DmxMode& l : (*profile)->modes)
        if (!same && l.footprint() == m.footprint()) same = &l;
      g.modeOf[m.name] = same ? same->name : (*profile)->modes.front().name;
      if (!modes.empty()) modes += ", ";
      modes += "\"" + m.name + "\" -> \"" + g.modeOf[m.name] + "\"" + (same ? "" : " (no mode of " + std::to_string(m.footprint()) + " channels)");
    }
    out_.show.profiles[g.profileKey] = ProfileRef{hit->file, std::nullopt, false};
    g.profile = *profile;
    out_.libraryMatches.push_back(what + ": a stub, matched to the library's " + hit->title() + " (" + hit->file + "); modes " + modes);
  }

  void addFixture(const FixtureSource& f, const GdtfEntry& g) {
    FixtureDef def;
    def.name = f.name.empty() ? g.profileKey : f.name;
    def.profile = g.profileKey;
    def.mode = f.mode;
    if (auto mapped = g.modeOf.find(f.mode); mapped != g.modeOf.end()) {
      def.mode = mapped->second;
    } else if (std::find(g.modes.begin(), g.modes.end(), f.mode) == g.modes.end()) {
      def.mode = g.modes.empty() ? "" : g.modes.front();
      out_.warnings.push_back(f.place + ": GDTFMode \"" + f.mode + "\" is not a mode of " + g.file + "; its first mode \"" + def.mode +
                              "\" is used");
    }
    def.id = fixtureId(f);
    // The uuid goes back out with an export, so the CAD program recognises its fixture; a
    // malformed or repeated one is dropped and the export makes a new one.
    if (isMvrUuid(f.uuid) && usedUuids_.insert(lowerAscii(f.uuid)).second) def.mvrUuid = f.uuid;
    else if (!f.uuid.empty()) out_.warnings.push_back(f.place + ": uuid \"" + f.uuid.substr(0, 40) + "\" is malformed or used twice; an export gives this fixture a new one");
    if (!f.address.empty()) {
      auto patch = parseMvrAddress(f.address);
      if (!patch.ok())
        out_.warnings.push_back(f.place + ": " + patch.error().message + "; left unpatched");
      else if (patch->universe > 0)
        def.patch = *patch;
    }
    // Placement: rotation from the matrix's axes (orthonormalised), position = origin + pivot.
    const glm::dmat4& w = f.worldMm;
    glm::dvec3 u(w[0]), v(w[1]);
    const double su = glm::length(u), sv = glm::length(v), swl = glm::length(glm::dvec3(w[2]));
    if (!(su > 1e-9) || !(sv > 1e-9)) {
      out_.warnings.push_back(f.place + ": its Matrix has a zero axis; the fixture is placed unrotated");
      u = {1, 0, 0};
      v = {0, 1, 0};
    }
    if (std::abs(su - 1) > 1e-3 || std::abs(sv - 1) > 1e-3 || std::abs(swl - 1) > 1e-3)
      out_.warnings.push_back(f.place + ": its Matrix scales (axis lengths " + std::to_string(su) + ", " + std::to_string(sv) + ", " +
                              std::to_string(swl) + "); the scale is dropped, fixtures keep their real size");
    u = glm::normalize(u);
    v = glm::normalize(v - u * glm::dot(u, v));
    glm::dvec3 wz = glm::cross(u, v);
    if (glm::dot(wz, glm::dvec3(w[2])) < 0)
      out_.warnings.push_back(f.place + ": its Matrix mirrors; imported as the rotation of its first two axes");
    const glm::dmat3 rot(u, v, wz);
    def.rotationDeg = mvrRotationToHazeDeg(rot);
    const glm::dmat3 hazeFromMvr(1, 0, 0, 0, 0, -1, 0, 1, 0);
    const glm::dmat3 rHaze = hazeFromMvr * rot * glm::transpose(hazeFromMvr);
    const glm::vec3 posM = mvrPointToHazeM(glm::dvec3(w[3])) + glm::vec3(rHaze * glm::dvec3(g.pivotOffsetM));
    def.position = glm::vec3(std::round(posM.x * 1e4f) / 1e4f, std::round(posM.y * 1e4f) / 1e4f, std::round(posM.z * 1e4f) / 1e4f);
    if (!f.focus.empty()) focusOf_.emplace_back(out_.show.fixtures.size(), f.focus);
    if (!f.groups.empty()) fixtureGroups_.emplace_back(def.id, f.groups);
    labels_.push_back(MvrFixtureLabel{trim(f.name), trim(f.fixtureId), trim(f.unitNumber), g.profileKey, def.id});
    out_.show.fixtures.push_back(def);
    beamDirs_.push_back(glm::vec3(rHaze * glm::dvec3(0.0, -1.0, 0.0)));
  }

  int fixtureId(const FixtureSource& f) {
    // Id: the FixtureID when it is a positive number not used yet, else the next free one.
    int id = 0;
    {
      char* end = nullptr;
      const long v = f.fixtureId.empty() ? 0 : std::strtol(f.fixtureId.c_str(), &end, 10);
      if (v > 0 && v < 1000000000 && end != nullptr && *end == '\0' && !usedIds_.count(static_cast<int>(v)))
        id = static_cast<int>(v);
      else if (v > 0 && usedIds_.count(static_cast<int>(v)))
        out_.warnings.push_back(f.place + ": FixtureID " + f.fixtureId + " is used twice; this fixture gets a new id");
    }
    if (id == 0) {
      while (takenIds_.count(nextId_) || usedIds_.count(nextId_)) ++nextId_;
      id = nextId_++;
    }
    usedIds_.insert(id);
    return id;
  }

  const ZipArchive& zip_;
  const std::string src_;
  SceneWalker& walker_;
  MvrImport& out_;
  std::filesystem::path showDir_;
  std::string stem_, gdtfDirName_;
  std::map<std::string, GdtfEntry> gdtfs_;  // by GDTFSpec
  std::set<std::string> usedKeys_;
  std::set<std::string> usedUuids_;  // lower case
  const MvrImportOptions& options_;
  std::optional<LibraryIndex> library_;  // indexed at the first stub
  std::set<int> takenIds_, usedIds_;
  int nextId_ = 1;
  std::vector<std::pair<std::size_t, std::string>> focusOf_;  // fixture index -> focus uuid
  std::vector<std::pair<int, std::vector<std::string>>> fixtureGroups_;  // fixture id -> its GroupObjects
  std::vector<MvrFixtureLabel> labels_;                       // per fixture, for its name
  std::vector<glm::vec3> beamDirs_;                           // by fixture: the beam at pan = tilt = 0, haze world
  std::vector<glm::vec3> venueTrianglesM_;
};

// The scene description parsed, or an error naming the line of malformed XML.
Status parseSceneXml(const ZipArchive& zip, const std::string& src, std::string& xml, pugi::xml_document& doc) {
  if (!zip.contains(kSceneXml))
    return Error{src, "", std::string("the archive has no ") + kSceneXml + "; an MVR file must contain it (is this an MVR?)"};
  auto xmlBytes = zip.read(kSceneXml);
  if (!xmlBytes.ok()) return xmlBytes.error();
  xml.assign(xmlBytes->begin(), xmlBytes->end());
  const pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size());
  if (!parsed) {
    const auto off = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, parsed.offset));
    const auto line = 1 + std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(std::min(off, xml.size())), '\n');
    return Error{src, std::string(kSceneXml) + " line " + std::to_string(line),
                 std::string("the XML is not well-formed (") + parsed.description() + ")"};
  }
  const pugi::xml_node root = doc.child("GeneralSceneDescription");
  if (!root || !root.child("Scene"))
    return Error{src, kSceneXml, "no <GeneralSceneDescription><Scene>; expected an MVR scene description"};
  return Ok{};
}

// The MVR itself beside the show (SHOW_source.mvr), byte for byte: `haze export-mvr` writes its
// layers, classes, trusses, scene objects, geometry and unknown elements back out from it.
Status keepSource(const std::filesystem::path& mvrFile, const std::filesystem::path& showFile, Show& show) {
  const std::string name = showStem(showFile) + "_source.mvr";
  const std::filesystem::path target = (showFile.parent_path().empty() ? std::filesystem::path(".") : showFile.parent_path()) / name;
  std::error_code ec;
  if (!std::filesystem::equivalent(mvrFile, target, ec)) {
    std::ifstream in(mvrFile, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) return Error{mvrFile.string(), "", "cannot read the MVR again to keep it beside the show"};
    if (Status w = writeFileAtomically(target, bytes, false); !w.ok()) return w.error();
  }
  show.mvrSource = name;
  return Ok{};
}

}  // namespace

Result<MvrImport> importMvr(const std::filesystem::path& mvrFile, const std::filesystem::path& showFile,
                            const MvrImportOptions& options) {
  const std::string src = mvrFile.string();
  std::error_code ec;
  if (!options.force && std::filesystem::exists(showFile, ec))
    return Error{showFile.string(), "", "the show file already exists; choose another name or pass --force"};
  auto zip = ZipArchive::open(mvrFile);
  if (!zip.ok()) return zip.error();
  std::string xml;
  pugi::xml_document doc;
  if (Status parsed = parseSceneXml(*zip, src, xml, doc); !parsed.ok()) return parsed.error();
  const pugi::xml_node root = doc.child("GeneralSceneDescription");

  MvrImport out;
  SceneWalker walker(xml, out.warnings);
  const int verMajor = root.attribute("verMajor").as_int(1);
  if (verMajor != 1) walker.warn(root, "MVR version " + std::to_string(verMajor) + " is not 1; read as version 1");
  walker.walkScene(root.child("Scene"));

  out.show.atmosphere.scattering = 0.03f;
  out.show.atmosphere.ambient = glm::vec3(0.02f);
  MvrImporter importer(*zip, src, showFile, walker, out, options);
  if (Status s = importer.addFixtures(); !s.ok()) return s.error();
  importer.addFocusCue();
  if (options.writeVenue)
    if (Status s = importer.writeVenue(options.maxVenueTriangles); !s.ok()) return s.error();
  importer.addOverviewCamera();

  if (options.keepSource)
    if (Status s = keepSource(mvrFile, showFile, out.show); !s.ok()) return s.error();

  SaveOptions save;
  save.force = true;  // existence was checked above; a new show has no stamp to compare
  save.keepBackup = false;
  Status s = saveShow(out.show, showFile, save);
  if (!s.ok()) return s.error();
  return out;
}

}  // namespace haze
