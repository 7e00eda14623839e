// haze show -> MVR: one Layer "haze" holding the show's groups as GroupObjects and its fixtures,
// one FocusPoint per aimed fixture, the GDTF files the profiles name embedded byte for byte.
#include "shows/import/mvr_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include <pugixml.hpp>

#include "fixtures/core/atomic_file.h"
#include "fixtures/core/text_file.h"
#include "fixtures/core/zip_archive.h"
#include "fixtures/core/zip_writer.h"
#include "fixtures/gdtf.h"
#include "fixtures/pose.h"
#include "shows/import/gdtf_export.h"
#include "shows/import/glb_pack.h"
#include "shows/import/mvr_import.h"
#include "shows/playback.h"
#include "shows/show_save.h"

namespace haze {

namespace {

// MVR world axis -> haze world axis (x, y, z) -> (x, z, -y), as the import's (mvr_frame.cpp).
const glm::dmat3 kMvrToHaze(1, 0, 0, 0, 0, -1, 0, 1, 0);

constexpr std::size_t kMaxGdtfBytes = 256ull << 20;  // one embedded GDTF; ZipArchive reads at most 128 MB an entry

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool endsWithGdtf(const std::string& path) {
  return path.size() > 5 && lower(path.substr(path.size() - 5)) == ".gdtf";
}

std::string uuidText(std::uint64_t hi, std::uint64_t lo) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%08x-%04x-%04x-%04x-%012llx", static_cast<unsigned>(hi >> 32),
                static_cast<unsigned>((hi >> 16) & 0xffff), static_cast<unsigned>(hi & 0xffff),
                static_cast<unsigned>(lo >> 48), static_cast<unsigned long long>(lo & 0xffffffffffffull));
  return buf;
}

// A uuid that depends only on `name` (layers, groups, focus points: the same show exports the
// same uuids). Two FNV-1a 64 hashes; version 8 (custom), RFC 4122 variant.
std::string nameUuid(const std::string& name) {
  auto fnv = [&](std::uint64_t h) {
    for (unsigned char c : name) h = (h ^ c) * 0x100000001b3ull;
    return h;
  };
  std::uint64_t hi = fnv(0xcbf29ce484222325ull), lo = fnv(0x84222325cbf29ce4ull);
  hi = (hi & ~0xf000ull) | 0x8000ull;
  lo = (lo & ~(0xc000ull << 48)) | (0x8000ull << 48);
  return uuidText(hi, lo);
}

std::string fixed(double v, int decimals) {
  if (std::abs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;  // no "-0.000000"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

Result<std::vector<std::uint8_t>> readBytes(const std::filesystem::path& file) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) return Error{file.string(), "", "cannot read the GDTF file (" + ec.message() + ")"};
  if (size > kMaxGdtfBytes) return Error{file.string(), "", "the GDTF file is larger than 256 MB; not embedded"};
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    return Error{file.string(), "", "cannot read the GDTF file"};
  return bytes;
}

// The import's reading of a placement (mvr_import.cpp): axes made orthonormal, Euler angles,
// the pivot added. Used to tell whether haze moved a fixture since the import.
struct ImportedPlacement {
  glm::vec3 rotationDeg{0.0f};
  glm::vec3 positionM{0.0f};
};
glm::dmat3 hazeRotation(const glm::vec3& rotationDeg) {
  return kMvrToHaze * glm::dmat3(hazeToMvrMatrix(glm::vec3(0.0f), rotationDeg, glm::vec3(0.0f))) * glm::transpose(kMvrToHaze);
}

ImportedPlacement importedPlacement(const glm::dmat4& worldMm, const glm::vec3& pivotOffsetM) {
  glm::dvec3 u(worldMm[0]), v(worldMm[1]);
  if (!(glm::length(u) > 1e-9) || !(glm::length(v) > 1e-9)) u = {1, 0, 0}, v = {0, 1, 0};
  u = glm::normalize(u);
  v = glm::normalize(v - u * glm::dot(u, v));
  ImportedPlacement p;
  p.rotationDeg = mvrRotationToHazeDeg(glm::dmat3(u, v, glm::cross(u, v)));
  p.positionM = mvrPointToHazeM(glm::dvec3(worldMm[3])) + glm::vec3(hazeRotation(p.rotationDeg) * glm::dvec3(pivotOffsetM));
  return p;
}

bool samePlacement(const FixtureDef& f, const ImportedPlacement& p) {
  const glm::dmat3 a = hazeRotation(f.rotationDeg), b = hazeRotation(p.rotationDeg);
  double d = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d < 1e-4 && glm::length(f.position - p.positionM) < 1.5e-4f;
}

// The child element `name` of `node` with `text`, made when missing.
void setChildText(pugi::xml_node node, const char* name, const std::string& text) {
  pugi::xml_node c = node.child(name);
  if (!c) c = node.append_child(name);
  c.text() = text.c_str();
}

struct ProfileOut {
  bool gdtf = false;
  std::string entry;  // archive name of the embedded GDTF
  glm::vec3 pivotOffsetM{0.0f};
  std::vector<std::string> modes;
};

class Exporter {
 public:
  Exporter(Show& show, const std::filesystem::path& mvrFile, const MvrExportOptions& options, MvrExport& out)
      : show_(show), src_(mvrFile.string()), options_(options), out_(out) {}

  Status loadProfiles() {
    auto loaded = haze::loadProfiles(show_);
    if (!loaded.ok()) return loaded.error();
    profiles_ = std::move(*loaded);
    std::set<std::string> usedEntries;
    for (const auto& [key, ref] : show_.profiles) {
      ProfileOut& p = out_profiles_[key];
      if (auto it = profiles_.find(key); it != profiles_.end())
        for (const DmxMode& m : it->second->modes) p.modes.push_back(m.name);
      if (ref.inlineObject || !endsWithGdtf(ref.path)) {
        writeOtherProfile(key, p, usedEntries);
        continue;
      }
      const std::filesystem::path file = show_.resolve(ref.path);
      auto gdtf = loadGdtf(file);
      if (!gdtf.ok()) return gdtf.error();
      auto bytes = readBytes(file);
      if (!bytes.ok()) return bytes.error();
      // The file's own name (a CAD program shows it); another profile's file of the same name gets a suffix.
      std::string entry = file.filename().string();
      for (int n = 2; !usedEntries.insert(lower(entry)).second; ++n)
        entry = file.stem().string() + "_" + std::to_string(n) + ".gdtf";
      p.gdtf = true;
      p.entry = entry;
      gdtfEntries_.insert(lower(entry));
      p.pivotOffsetM = gdtf->pivotOffsetM;
      files_.push_back({entry, std::move(*bytes), true});
      ++out_.gdtfFiles;
    }
    return Ok{};
  }

  // A native, IES or EULUMDAT profile as a GDTF written here (shows/import/gdtf_export.h), with
  // a warning of what it leaves out; a profile that cannot be written is warned and its fixtures
  // go out without a GDTFSpec.
  void writeOtherProfile(const std::string& key, ProfileOut& p, std::set<std::string>& usedEntries) {
    auto it = profiles_.find(key);
    if (it == profiles_.end()) return;
    auto gdtf = profileToGdtf(*it->second, key, nameUuid("haze gdtf " + key));
    if (!gdtf.ok()) {
      out_.warnings.push_back("profile \"" + key + "\" cannot be written as GDTF (" + gdtf.error().str() + ")");
      return;
    }
    std::string stem = key;
    for (char& c : stem)
      if (c == '/' || c == '\\' || c == ':' || static_cast<unsigned char>(c) < 32) c = '_';
    std::string entry = stem + ".gdtf";
    for (int n = 2; !usedEntries.insert(lower(entry)).second; ++n) entry = stem + "_" + std::to_string(n) + ".gdtf";
    p.gdtf = true;
    p.entry = entry;
    gdtfEntries_.insert(lower(entry));
    files_.push_back({entry, std::move(gdtf->bytes), true});
    ++out_.gdtfFiles;
    ++out_.gdtfWritten;
    std::string lost;
    for (const std::string& n : gdtf->notCarried) lost += (lost.empty() ? "" : "; ") + n;
    out_.warnings.push_back("profile \"" + key + "\" is written as the GDTF " + entry +
                            (lost.empty() ? std::string() : ", without " + lost));
  }

  // The venue as one .glb for a SceneObject (a show written from itself alone; over a source
  // MVR, the source's own geometry is the venue). A venue that cannot be packed is warned.
  void packVenue() {
    if (show_.venueGltf.empty()) return;
    auto glb = packGlb(show_.resolve(show_.venueGltf));
    if (!glb.ok()) {
      out_.warnings.push_back("the venue is not in the file: " + glb.error().str());
      return;
    }
    venueEntry_ = "venue.glb";
    files_.push_back({venueEntry_, std::move(*glb), true});
    out_.venueGlb = true;
  }

  // Where each aimed fixture's beam meets the floor (haze y = 0, MVR z = 0), or 10 m out when it
  // does not go down: the point the import aims it at again.
  void findFocusPoints() {
    const CueList* list = options_.focusList.empty() ? nullptr : show_.findCueList(options_.focusList);
    if (list == nullptr || list->cues.empty()) return;
    std::size_t cueIndex = 0;
    if (!options_.focusCue.empty()) {
      auto found = findCue(*list, options_.focusCue);
      if (!found.ok()) {
        out_.warnings.push_back("cue list \"" + list->name + "\" has no cue " + options_.focusCue + "; no focus points written");
        return;
      }
      cueIndex = *found;
    }
    std::set<int> aimed;
    for (std::size_t i = 0; i <= cueIndex; ++i)
      for (const auto& [id, v] : list->cues[i].values)
        if (v.panDeg || v.tiltDeg) aimed.insert(id);
    const StageState state = trackedState(show_, profiles_, *list, cueIndex);
    for (const FixtureDef& f : show_.fixtures) {
      auto st = state.find(f.id);
      auto prof = profiles_.find(f.profile);
      if (!aimed.count(f.id) || st == state.end() || prof == profiles_.end()) continue;
      const BeamPose pose = beamPose(f.position, f.rotationDeg, st->second.panDeg, st->second.tiltDeg, prof->second->lensOffset);
      float t = 10.0f;
      if (pose.zb.y < -1e-3f && pose.lensPosition.y > 0.0f) t = std::min(100.0f, -pose.lensPosition.y / pose.zb.y);
      focusM_[f.id] = pose.lensPosition + t * pose.zb;
      focusLens_[f.id] = pose.lensPosition;
    }
  }

  // The show over the MVR it was imported from: that file's XML with each of the show's
  // fixtures updated in place where haze changed it, fixtures haze deleted removed, new ones
  // added in a layer "haze"; every other element and every other file of the archive as it was.
  Status writeOverSource(const std::filesystem::path& sourceFile) {
    auto zip = ZipArchive::open(sourceFile);
    if (!zip.ok()) return zip.error();
    auto xmlBytes = zip->read("GeneralSceneDescription.xml");
    if (!xmlBytes.ok()) return xmlBytes.error();
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed =
        doc.load_buffer(xmlBytes->data(), xmlBytes->size(), pugi::parse_full | pugi::parse_ws_pcdata);
    pugi::xml_node root = doc.child("GeneralSceneDescription");
    if (!parsed || !root.child("Scene").child("Layers"))
      return Error{sourceFile.string(), "GeneralSceneDescription.xml", "not an MVR scene description any more; export without it (remove \"mvr\" from the show)"};
    out_.version = std::string(root.attribute("verMajor").as_string("1")) + "." + root.attribute("verMinor").as_string("0");
    setAttribute(root, "provider", "haze");
    setAttribute(root, "providerVersion", options_.providerVersion);

    for (std::size_t i = 0; i < show_.fixtures.size(); ++i) byUuid_[lower(show_.fixtures[i].mvrUuid)] = i;
    pugi::xml_node layers = root.child("Scene").child("Layers");
    for (pugi::xml_node layer : layers.children("Layer")) {
      glm::dmat4 world(1.0);
      if (pugi::xml_node m = layer.child("Matrix"))
        if (auto parsedM = parseMvrMatrix(m.text().as_string()); parsedM.ok()) world = *parsedM;
      collectFocusPoints(layer.child("ChildList"), world, 0);
    }
    for (pugi::xml_node layer : layers.children("Layer")) {
      glm::dmat4 world(1.0);
      if (pugi::xml_node m = layer.child("Matrix"))
        if (auto parsedM = parseMvrMatrix(m.text().as_string()); parsedM.ok()) world = *parsedM;
      updateFixtures(layer.child("ChildList"), world, 0);
    }
    for (pugi::xml_node gone : removed_) gone.parent().remove_child(gone);
    out_.fixturesRemoved = static_cast<int>(removed_.size());

    // Fixtures new in haze, and new focus points, go into the layer "haze".
    std::vector<const FixtureDef*> added;
    for (std::size_t i = 0; i < show_.fixtures.size(); ++i)
      if (!written_.count(i)) added.push_back(&show_.fixtures[i]);
    if (!added.empty() || !newFocus_.empty()) {
      pugi::xml_node layer = layers.find_child_by_attribute("Layer", "name", "haze");
      if (!layer) {
        layer = layers.append_child("Layer");
        layer.append_attribute("name") = "haze";
        layer.append_attribute("uuid") = layerUuid().c_str();
      }
      pugi::xml_node children = layer.child("ChildList");
      if (!children) children = layer.append_child("ChildList");
      // mvr.xsd's ChildList order: focus points before fixtures, trusses and the rest.
      pugi::xml_node before;
      for (pugi::xml_node c : children.children())
        if (c.type() == pugi::node_element && std::string(c.name()) != "SceneObject" && std::string(c.name()) != "GroupObject" &&
            std::string(c.name()) != "FocusPoint") {
          before = c;
          break;
        }
      for (const FixtureDef* f : newFocus_) {
        pugi::xml_node fp = before ? children.insert_child_before("FocusPoint", before) : children.append_child("FocusPoint");
        writeFocusPoint(fp, *f);
      }
      for (const FixtureDef* f : added) writeFixture(children, *f);
    }
    out_.fixtureCount = static_cast<int>(show_.fixtures.size());

    std::ostringstream xml;
    doc.save(xml, "", pugi::format_raw, pugi::encoding_utf8);
    const std::string text = xml.str();
    std::vector<ZipWriteEntry> entries;
    entries.push_back({"GeneralSceneDescription.xml", std::vector<std::uint8_t>(text.begin(), text.end()), true});
    std::set<std::string> showFiles;
    for (const ZipWriteEntry& e : files_) showFiles.insert(lower(e.name));
    for (const ZipEntry& e : zip->entries()) {
      if (e.name == "GeneralSceneDescription.xml" || showFiles.count(lower(e.name))) continue;
      auto bytes = zip->read(e.name);
      if (!bytes.ok()) return bytes.error();
      entries.push_back({e.name, std::move(*bytes), true});
      ++out_.filesKept;
    }
    for (ZipWriteEntry& e : files_) entries.push_back(std::move(e));
    auto archive = zipToMemory(entries, src_);
    if (!archive.ok()) return archive.error();
    return writeFileAtomically(src_, std::string_view(reinterpret_cast<const char*>(archive->data()), archive->size()), false);
  }

  Status write() {
    pugi::xml_document doc;
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    decl.append_attribute("encoding") = "UTF-8";
    decl.append_attribute("standalone") = "no";
    pugi::xml_node root = doc.append_child("GeneralSceneDescription");
    root.append_attribute("verMajor") = kMvrExportVerMajor;
    root.append_attribute("verMinor") = kMvrExportVerMinor;
    out_.version = std::to_string(kMvrExportVerMajor) + "." + std::to_string(kMvrExportVerMinor);
    root.append_attribute("provider") = "haze";
    root.append_attribute("providerVersion") = options_.providerVersion.c_str();
    root.append_child("UserData");
    pugi::xml_node scene = root.append_child("Scene");
    pugi::xml_node layers = scene.append_child("Layers");
    pugi::xml_node layer = layers.append_child("Layer");
    layer.append_attribute("name") = "haze";
    layer.append_attribute("uuid") = layerUuid().c_str();
    pugi::xml_node children = layer.append_child("ChildList");
    writeChildren(children);
    scene.append_child("AUXData");

    std::ostringstream xml;
    doc.save(xml, "  ", pugi::format_default, pugi::encoding_utf8);
    const std::string text = xml.str();
    std::vector<ZipWriteEntry> entries;
    entries.push_back({"GeneralSceneDescription.xml", std::vector<std::uint8_t>(text.begin(), text.end()), true});
    for (ZipWriteEntry& e : files_) entries.push_back(std::move(e));
    auto zip = zipToMemory(entries, src_);
    if (!zip.ok()) return zip.error();
    return writeFileAtomically(src_, std::string_view(reinterpret_cast<const char*>(zip->data()), zip->size()), false);
  }

 private:
  std::string layerUuid() const {
    // Named after the first fixture's uuid so that it stays the same while the rig does.
    return nameUuid("haze layer " + (show_.fixtures.empty() ? std::string() : lower(show_.fixtures.front().mvrUuid)));
  }

  // mvr.xsd's ChildList is a sequence: scene objects, group objects, focus points, fixtures.
  void writeChildren(pugi::xml_node children) {
    if (!venueEntry_.empty()) {
      // glTF files in MVR are metres, Y up: haze's own frame, so the venue needs no Matrix.
      pugi::xml_node venue = children.append_child("SceneObject");
      venue.append_attribute("name") = "Venue";
      venue.append_attribute("uuid") = nameUuid("haze venue " + layerUuid()).c_str();
      venue.append_child("Geometries").append_child("Geometry3D").append_attribute("fileName") = venueEntry_.c_str();
      venue.append_child("FixtureID");
      venue.append_child("FixtureIDNumeric").text() = "0";
      venue.append_child("ChildList");
    }
    std::map<int, std::string> groupOf;  // fixture id -> the first group that holds it
    std::map<int, int> extraGroups;
    for (const GroupDef& g : show_.groups)
      for (int id : g.fixtures)
        if (!groupOf.emplace(id, g.name).second && groupOf[id] != g.name) ++extraGroups[id];
    if (!extraGroups.empty())
      out_.warnings.push_back(std::to_string(extraGroups.size()) +
                              " fixtures are in more than one group; an MVR object has one place, so each is written in "
                              "its first group only (fixture " + std::to_string(extraGroups.begin()->first) + ", ...)");
    for (const GroupDef& g : show_.groups) {
      bool any = false;
      for (int id : g.fixtures) any = any || (groupOf[id] == g.name && show_.findFixture(id));
      if (!any) continue;
      pugi::xml_node go = children.append_child("GroupObject");
      go.append_attribute("name") = g.name.c_str();
      go.append_attribute("uuid") = nameUuid("haze group " + layerUuid() + " " + g.name).c_str();
      pugi::xml_node list = go.append_child("ChildList");
      for (const FixtureDef& f : show_.fixtures)
        if (auto it = groupOf.find(f.id); it != groupOf.end() && it->second == g.name) writeFixture(list, f);
      ++out_.groupObjects;
    }
    for (const FixtureDef& f : show_.fixtures) {
      auto it = focusM_.find(f.id);
      if (it == focusM_.end()) continue;
      writeFocusPoint(children.append_child("FocusPoint"), f);
    }
    for (const FixtureDef& f : show_.fixtures)
      if (!groupOf.count(f.id)) writeFixture(children, f);
  }

  std::string focusUuid(const FixtureDef& f) const { return nameUuid("haze focus " + lower(f.mvrUuid)); }

  static void setAttribute(pugi::xml_node n, const char* name, const std::string& value) {
    pugi::xml_attribute a = n.attribute(name);
    if (!a) a = n.append_attribute(name);
    a = value.c_str();
  }

  void writeFocusPoint(pugi::xml_node fp, const FixtureDef& f) {
    fp.append_attribute("name") = ("Focus " + std::to_string(f.id)).c_str();
    fp.append_attribute("uuid") = focusUuid(f).c_str();
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(glm::transpose(kMvrToHaze) * glm::dvec3(focusM_.at(f.id)) * 1000.0, 1.0);
    fp.append_child("Matrix").text() = formatMvrMatrix(m).c_str();
    fp.append_child("Geometries");
    ++out_.focusPoints;
  }

  glm::dmat4 matrixOf(pugi::xml_node n, const glm::dmat4& parent) const {
    pugi::xml_node m = n.child("Matrix");
    if (!m) return parent;
    auto parsed = parseMvrMatrix(m.text().as_string());
    return parsed.ok() ? parent * *parsed : parent;  // as the import: a bad Matrix is the identity
  }

  void collectFocusPoints(pugi::xml_node list, const glm::dmat4& parent, int depth) {
    if (!list || depth > 32) return;
    for (pugi::xml_node n : list.children()) {
      if (n.type() != pugi::node_element) continue;
      const glm::dmat4 world = matrixOf(n, parent);
      if (std::string(n.name()) == "FocusPoint") sourceFocusM_[lower(n.attribute("uuid").value())] = mvrPointToHazeM(glm::dvec3(world[3]));
      collectFocusPoints(n.child("ChildList"), world, depth + 1);
    }
  }

  // Whether the GDTFSpec names a fixture type the show has (so a fixture of it that the show
  // lacks was deleted in haze, not left out by the import).
  bool showHasType(const std::string& spec) const {
    std::string name = lower(spec);
    if (name.size() < 5 || name.substr(name.size() - 5) != ".gdtf") name += ".gdtf";
    return gdtfEntries_.count(name) > 0;
  }

  void updateFixtures(pugi::xml_node list, const glm::dmat4& parent, int depth) {
    if (!list || depth > 32) return;
    for (pugi::xml_node n : list.children()) {
      if (n.type() != pugi::node_element) continue;
      const glm::dmat4 world = matrixOf(n, parent);
      if (std::string(n.name()) == "Fixture") {
        auto it = byUuid_.find(lower(n.attribute("uuid").value()));
        if (it != byUuid_.end() && !written_.count(it->second)) {
          written_.insert(it->second);
          updateFixture(n, parent, world, show_.fixtures[it->second]);
        } else if (showHasType(n.child("GDTFSpec").text().as_string())) {
          removed_.push_back(n);
          continue;
        }
      }
      updateFixtures(n.child("ChildList"), world, depth + 1);
    }
  }

  void updateFixture(pugi::xml_node x, const glm::dmat4& parent, const glm::dmat4& world, const FixtureDef& f) {
    const ProfileOut& p = out_profiles_[f.profile];
    if (!samePlacement(f, importedPlacement(world, p.pivotOffsetM))) {
      const glm::dmat4 local = glm::inverse(parent) * hazeToMvrMatrix(f.position, f.rotationDeg, p.pivotOffsetM);
      if (!x.child("Matrix")) x.prepend_child("Matrix");
      x.child("Matrix").text() = formatMvrMatrix(local).c_str();
      ++out_.fixturesChanged;
    }
    const std::string sourceName = x.attribute("name").value();
    // A name the import composed (the MVR's name with its FixtureID, ...) is the MVR's own name.
    const MvrFixtureLabel label{sourceName, trim(x.child("FixtureID").text().as_string()), trim(x.child("UnitNumber").text().as_string()),
                                f.profile, f.id};
    if (sourceName != f.name && !isMvrComposedName(f.name, label) && !(sourceName.empty() && f.name == f.profile))
      setAttribute(x, "name", f.name);
    if (p.gdtf) {
      std::string spec = lower(x.child("GDTFSpec").text().as_string());
      if (spec.size() < 5 || spec.substr(spec.size() - 5) != ".gdtf") spec += ".gdtf";
      if (spec != lower(p.entry)) setChildText(x, "GDTFSpec", p.entry);
      if (!f.mode.empty() && f.mode != x.child("GDTFMode").text().as_string()) setChildText(x, "GDTFMode", f.mode);
    }
    const std::string id = std::to_string(f.id);
    if (id != x.child("FixtureID").text().as_string()) {
      setChildText(x, "FixtureID", id);
      if (x.child("FixtureIDNumeric")) setChildText(x, "FixtureIDNumeric", id);
    }
    // The patch: break 0 (else the first address), as the import reads it.
    pugi::xml_node address;
    for (pugi::xml_node a : x.child("Addresses").children("Address"))
      if (!address || a.attribute("break").as_int(0) == 0) {
        address = a;
        if (a.attribute("break").as_int(0) == 0) break;
      }
    std::optional<Patch> sourcePatch;
    if (address)
      if (auto parsedPatch = parseMvrAddress(address.text().as_string()); parsedPatch.ok() && parsedPatch->universe > 0) sourcePatch = *parsedPatch;
    const bool samePatch = sourcePatch.has_value() == f.patch.has_value() &&
                           (!f.patch || (sourcePatch->universe == f.patch->universe && sourcePatch->address == f.patch->address));
    if (!samePatch) {
      if (!address) {
        pugi::xml_node addresses = x.child("Addresses") ? x.child("Addresses") : x.append_child("Addresses");
        address = addresses.append_child("Address");
        address.append_attribute("break") = 0;
      }
      address.text() = (f.patch ? std::to_string(static_cast<long long>(f.patch->universe - 1) * 512 + f.patch->address) : std::string("0")).c_str();
    }
    // The focus: kept while the beam still goes through the point; else a new point on the beam.
    if (auto aim = focusM_.find(f.id); aim != focusM_.end()) {
      auto fp = sourceFocusM_.find(lower(x.child("Focus").text().as_string()));
      bool onBeam = false;
      if (fp != sourceFocusM_.end()) {
        const glm::vec3 lens = focusLens_.at(f.id), dir = glm::normalize(aim->second - lens);
        const glm::vec3 d = fp->second - lens;
        // 1 mm, plus what pan and tilt stored to 0.01 degree miss by at the point's distance.
        onBeam = glm::dot(d, dir) > 0.0f && glm::length(d - glm::dot(d, dir) * dir) < 1e-3f + 4e-4f * glm::length(d);
      }
      if (!onBeam) {
        setChildText(x, "Focus", focusUuid(f));
        newFocus_.push_back(&f);
      }
    }
  }

  void writeFixture(pugi::xml_node parent, const FixtureDef& f) {
    const ProfileOut& p = out_profiles_[f.profile];
    pugi::xml_node x = parent.append_child("Fixture");
    x.append_attribute("name") = (f.name.empty() ? f.profile : f.name).c_str();
    x.append_attribute("uuid") = f.mvrUuid.c_str();
    x.append_child("Matrix").text() = formatMvrMatrix(hazeToMvrMatrix(f.position, f.rotationDeg, p.pivotOffsetM)).c_str();
    if (p.gdtf) {
      x.append_child("GDTFSpec").text() = p.entry.c_str();
      const std::string mode = !f.mode.empty() ? f.mode : p.modes.empty() ? "" : p.modes.front();
      x.append_child("GDTFMode").text() = mode.c_str();
    } else if (notGdtf_.insert(f.profile).second) {
      out_.warnings.push_back("profile \"" + f.profile + "\" has no GDTF; its fixtures are written without a GDTFSpec (a CAD "
                              "program shows them as generic objects, an import leaves them out)");
    }
    if (focusM_.count(f.id)) x.append_child("Focus").text() = focusUuid(f).c_str();
    x.append_child("FixtureID").text() = std::to_string(f.id).c_str();
    x.append_child("FixtureIDNumeric").text() = std::to_string(f.id).c_str();
    x.append_child("UnitNumber").text() = "0";
    if (f.patch) {
      pugi::xml_node a = x.append_child("Addresses").append_child("Address");
      a.append_attribute("break") = 0;
      a.text() = std::to_string(static_cast<long long>(f.patch->universe - 1) * 512 + f.patch->address).c_str();
    }
    x.append_child("ChildList");
    ++out_.fixtureCount;
  }

  Show& show_;
  const std::string src_;
  const MvrExportOptions& options_;
  MvrExport& out_;
  ProfileSet profiles_;
  std::map<std::string, ProfileOut> out_profiles_;
  std::vector<ZipWriteEntry> files_;
  std::map<int, glm::vec3> focusM_;  // fixture id -> focus point, haze world metres
  std::set<std::string> notGdtf_;
  std::set<std::string> gdtfEntries_;  // lower case archive names of the show's GDTFs
  std::string venueEntry_;              // "venue.glb" when the venue is packed
  std::map<int, glm::vec3> focusLens_;  // fixture id -> its lens at the focus cue
  // Over a source MVR:
  std::map<std::string, std::size_t> byUuid_;  // lower-case uuid -> show fixture
  std::set<std::size_t> written_;
  std::vector<pugi::xml_node> removed_;
  std::map<std::string, glm::vec3> sourceFocusM_;  // lower-case uuid -> haze world
  std::vector<const FixtureDef*> newFocus_;
};

}  // namespace

std::string makeMvrUuid() {
  static thread_local std::mt19937_64 rng([] {
    std::random_device rd;
    std::seed_seq seq{rd(), rd(), rd(), rd(), rd(), rd(), rd(), rd()};
    return std::mt19937_64(seq);
  }());
  std::uint64_t hi = rng(), lo = rng();
  hi = (hi & ~0xf000ull) | 0x4000ull;
  lo = (lo & ~(0xc000ull << 48)) | (0x8000ull << 48);
  return uuidText(hi, lo);
}

int assignMvrUuids(Show& show) {
  std::set<std::string> used;
  int made = 0;
  for (FixtureDef& f : show.fixtures) {
    if (isMvrUuid(f.mvrUuid) && used.insert(lower(f.mvrUuid)).second) continue;
    do f.mvrUuid = makeMvrUuid();
    while (!used.insert(f.mvrUuid).second);
    ++made;
  }
  return made;
}

glm::dmat4 hazeToMvrMatrix(const glm::vec3& positionM, const glm::vec3& rotationDeg, const glm::vec3& pivotOffsetM) {
  // R = Rz * Ry * Rx in double, so the matrix does not carry float rounding into the file.
  const double k = 3.14159265358979323846 / 180.0;
  const double a = rotationDeg.x * k, b = rotationDeg.y * k, c = rotationDeg.z * k;
  const glm::dmat3 rx(1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a));
  const glm::dmat3 ry(std::cos(b), 0, -std::sin(b), 0, 1, 0, std::sin(b), 0, std::cos(b));
  const glm::dmat3 rz(std::cos(c), std::sin(c), 0, -std::sin(c), std::cos(c), 0, 0, 0, 1);
  const glm::dmat3 rHaze = rz * ry * rx;
  // The import: R_haze = C R_mvr C^T and position = C o / 1000 + R_haze pivot.
  const glm::dmat3 rMvr = glm::transpose(kMvrToHaze) * rHaze * kMvrToHaze;
  const glm::dvec3 originMm =
      glm::transpose(kMvrToHaze) * (glm::dvec3(positionM) - rHaze * glm::dvec3(pivotOffsetM)) * 1000.0;
  glm::dmat4 m(rMvr);
  m[3] = glm::dvec4(originMm, 1.0);
  return m;
}

std::string formatMvrMatrix(const glm::dmat4& m) {
  std::string s;
  for (int col = 0; col < 4; ++col) {
    s += "{";
    for (int row = 0; row < 3; ++row) s += (row ? "," : "") + fixed(m[col][row], col == 3 ? 4 : 9);
    s += "}";
  }
  return s;
}

Result<MvrExport> exportMvr(Show& show, const std::filesystem::path& mvrFile, const MvrExportOptions& options) {
  std::error_code ec;
  if (!options.force && std::filesystem::exists(mvrFile, ec))
    return Error{mvrFile.string(), "", "the file already exists; choose another name or pass --force"};
  MvrExport out;
  out.uuidsMade = assignMvrUuids(show);
  Exporter exporter(show, mvrFile, options, out);
  if (Status s = exporter.loadProfiles(); !s.ok()) return s.error();
  exporter.findFocusPoints();
  std::error_code sourceEc;
  if (!show.mvrSource.empty() && options.overSource && std::filesystem::exists(show.resolve(show.mvrSource), sourceEc)) {
    out.source = show.resolve(show.mvrSource).string();
    if (Status s = exporter.writeOverSource(show.resolve(show.mvrSource)); !s.ok()) return s.error();
  } else {
    if (!show.mvrSource.empty() && options.overSource)
      out.warnings.push_back("the show's MVR source " + show.resolve(show.mvrSource).string() +
                             " is missing; written from the show alone (its trusses, scene objects and layers are not in the file)");
    exporter.packVenue();
    if (Status s = exporter.write(); !s.ok()) return s.error();
  }
  return out;
}

Result<MvrExport> exportMvrFromShowFile(const std::filesystem::path& showFile, const std::filesystem::path& mvrFile,
                                        const MvrExportOptions& options) {
  std::error_code ec;
  if (!options.force && std::filesystem::exists(mvrFile, ec))
    return Error{mvrFile.string(), "", "the file already exists; choose another name or pass --force"};
  auto show = loadShow(showFile);
  if (!show.ok()) return show.error();
  const int made = assignMvrUuids(*show);
  if (made > 0)
    if (Status s = saveShow(*show, showFile); !s.ok()) return s.error();
  auto out = exportMvr(*show, mvrFile, options);
  if (out.ok()) out->uuidsMade = made;
  return out;
}

}  // namespace haze
