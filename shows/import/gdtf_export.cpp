// profileToGdtf: description.xml built with pugixml from the Profile, zipped in memory. The
// attribute names are those the GDTF import reads (fixtures/gdtf_dmx.cpp), so the file comes back
// as the same modes and channels.
#include "shows/import/gdtf_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <pugixml.hpp>

#include "fixtures/core/zip_writer.h"
#include "fixtures/facts.h"

namespace haze {

namespace {

struct GdtfAttribute {
  std::string name;     // "Dimmer", "Gobo2Pos"
  std::string feature;  // "Dimmer.Dimmer"
};

// The GDTF attribute of a haze channel; "" for what GDTF in haze's reading has no name for.
// The slots (0-based, coarse first) that carry the value of the coarse channel at `coarse`: its
// finer bytes are the mode's channels of the same attribute, wheel and cells with byte 1, 2, and
// they need not follow it (a QLC+ mode may list Pan, Tilt, Pan fine, Tilt fine).
std::vector<std::size_t> valueSlots(const DmxMode& m, std::size_t coarse) {
  const DmxChannel& c = m.channels[coarse];
  std::vector<std::size_t> slots{coarse};
  for (int b = 1; b < c.bytes; ++b)
    for (std::size_t j = 0; j < m.channels.size(); ++j) {
      const DmxChannel& f = m.channels[j];
      if (f.byte == b && f.attribute == c.attribute && f.wheel == c.wheel && f.cells == c.cells) {
        slots.push_back(j);
        break;
      }
    }
  return slots;
}

GdtfAttribute gdtfAttribute(const DmxChannel& c) {
  const std::string n = std::to_string(c.wheel + 1);
  switch (c.attribute) {
    case DmxAttribute::Intensity: return {"Dimmer", "Dimmer.Dimmer"};
    case DmxAttribute::Pan: return {"Pan", "Position.PanTilt"};
    case DmxAttribute::Tilt: return {"Tilt", "Position.PanTilt"};
    case DmxAttribute::Zoom: return {"Zoom", "Focus.Focus"};
    case DmxAttribute::GateFocus: return {"Focus1", "Focus.Focus"};
    case DmxAttribute::Iris: return {"Iris", "Beam.Beam"};
    case DmxAttribute::Gobo: return {"Gobo" + n, "Gobo.Gobo"};
    case DmxAttribute::GoboRotation: return {"Gobo" + n + "Pos", "Gobo.Gobo"};
    case DmxAttribute::GoboSpin: return {"Gobo" + n + "PosRotate", "Gobo.Gobo"};
    case DmxAttribute::Red: return {"ColorAdd_R", "Color.RGB"};
    case DmxAttribute::Green: return {"ColorAdd_G", "Color.RGB"};
    case DmxAttribute::Blue: return {"ColorAdd_B", "Color.RGB"};
    case DmxAttribute::White: return {"ColorAdd_W", "Color.RGB"};
    case DmxAttribute::Cyan: return {"ColorSub_C", "Color.RGB"};
    case DmxAttribute::Magenta: return {"ColorSub_M", "Color.RGB"};
    case DmxAttribute::Yellow: return {"ColorSub_Y", "Color.RGB"};
    case DmxAttribute::ColorWheel: return {"Color" + n, "Color.Color"};
    case DmxAttribute::Shutter: return {"Shutter1", "Beam.Beam"};
    case DmxAttribute::Frost: return {"Frost1", "Beam.Beam"};
    case DmxAttribute::PrismSpin: return {"Prism1PosRotate", "Beam.Beam"};
    case DmxAttribute::PrismRotation: return {"Prism1Pos", "Beam.Beam"};
    default: return {};
  }
}

std::string num(double v) {
  if (std::abs(v) < 1e-9) v = 0.0;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A linear Rec. 709 filter as GDTF's CIE 1931 xyY (Y in percent).
std::string xyY(const glm::vec3& rgb) {
  const double x = 0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b;
  const double y = 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
  const double z = 0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b;
  const double sum = x + y + z;
  if (!(sum > 1e-9)) return "0.3127,0.3290,0";
  return num(x / sum) + "," + num(y / sum) + "," + num(std::min(100.0, 100.0 * y));
}

std::string position(const glm::vec3& gdtfM) {
  return "{1,0,0," + num(gdtfM.x) + "}{0,1,0," + num(gdtfM.y) + "}{0,0,1," + num(gdtfM.z) + "}{0,0,0,1}";
}

void addWheels(pugi::xml_node wheels, const std::vector<Wheel>& list, const std::string& prefix, bool color,
               std::vector<std::string>& notCarried) {
  bool images = false;
  for (std::size_t w = 0; w < list.size(); ++w) {
    pugi::xml_node wheel = wheels.append_child("Wheel");
    wheel.append_attribute("Name") = (prefix + std::to_string(w + 1)).c_str();
    for (const WheelSlot& s : list[w].slots) {
      pugi::xml_node slot = wheel.append_child("Slot");
      slot.append_attribute("Name") = s.name.c_str();
      if (color && s.color) slot.append_attribute("Color") = xyY(*s.color).c_str();
      images = images || !s.imagePath.empty();
    }
  }
  if (images) notCarried.push_back("the gobo images (the wheel's slots are named, their pictures are not in the GDTF)");
}

}  // namespace

Result<GdtfWrite> profileToGdtf(const Profile& profile, const std::string& typeName, const std::string& fixtureTypeId) {
  GdtfWrite out;
  if (!profile.distribution) return Error{typeName, "", "the profile has no photometry to write"};
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node gdtf = doc.append_child("GDTF");
  gdtf.append_attribute("DataVersion") = "1.2";
  pugi::xml_node ft = gdtf.append_child("FixtureType");
  ft.append_attribute("Name") = typeName.c_str();
  ft.append_attribute("ShortName") = typeName.c_str();
  ft.append_attribute("LongName") = (profile.name.empty() ? typeName : profile.name).c_str();
  ft.append_attribute("Manufacturer") = (profile.manufacturer.empty() ? std::string("haze") : profile.manufacturer).c_str();
  ft.append_attribute("Description") = "written by haze from a non-GDTF profile";
  ft.append_attribute("FixtureTypeID") = fixtureTypeId.c_str();
  ft.append_attribute("Thumbnail") = "";
  ft.append_attribute("RefFT") = "";

  // Attributes: the ones the modes use, each with its feature group.
  std::map<std::string, std::string> attributes;  // name -> feature
  bool unnamed = false;
  for (const DmxMode& m : profile.modes)
    for (const DmxChannel& c : m.channels) {
      const GdtfAttribute a = gdtfAttribute(c);
      if (!a.name.empty()) attributes[a.name] = a.feature;
      else unnamed = unnamed || c.attribute != DmxAttribute::None;
    }
  attributes["NoFeature"] = "Control.Control";
  pugi::xml_node defs = ft.append_child("AttributeDefinitions");
  pugi::xml_node groups = defs.append_child("FeatureGroups");
  std::map<std::string, std::set<std::string>> features;
  for (const auto& [name, feature] : attributes) {
    const auto dot = feature.find('.');
    features[feature.substr(0, dot)].insert(feature.substr(dot + 1));
  }
  for (const auto& [group, names] : features) {
    pugi::xml_node g = groups.append_child("FeatureGroup");
    g.append_attribute("Name") = group.c_str();
    g.append_attribute("Pretty") = group.c_str();
    for (const std::string& f : names) g.append_child("Feature").append_attribute("Name") = f.c_str();
  }
  pugi::xml_node attrs = defs.append_child("Attributes");
  for (const auto& [name, feature] : attributes) {
    pugi::xml_node a = attrs.append_child("Attribute");
    a.append_attribute("Name") = name.c_str();
    a.append_attribute("Pretty") = name.c_str();
    a.append_attribute("Feature") = feature.c_str();
  }

  pugi::xml_node wheels = ft.append_child("Wheels");
  addWheels(wheels, profile.colorWheels, "Color", true, out.notCarried);
  addWheels(wheels, profile.goboWheels, "Gobo", false, out.notCarried);
  ft.append_child("PhysicalDescriptions");
  ft.append_child("Models");

  // Base > Yoke (pan) > Head (tilt) > Beam: both axes at the origin, so the GDTF origin is the
  // pivot haze places. The lens offset is haze's head frame (x, y, z) = GDTF (x, z, -y).
  const BeamAngles angles = beamAngles(*profile.distribution);
  const double lumens = lumensOf(*profile.distribution);
  pugi::xml_node geometries = ft.append_child("Geometries");
  pugi::xml_node base = geometries.append_child("Geometry");
  base.append_attribute("Name") = "Base";
  base.append_attribute("Position") = position(glm::vec3(0.0f)).c_str();
  pugi::xml_node yoke = base.append_child("Axis");
  yoke.append_attribute("Name") = "Yoke";
  yoke.append_attribute("Position") = position(glm::vec3(0.0f)).c_str();
  pugi::xml_node head = yoke.append_child("Axis");
  head.append_attribute("Name") = "Head";
  head.append_attribute("Position") = position(glm::vec3(0.0f)).c_str();
  pugi::xml_node beam = head.append_child("Beam");
  beam.append_attribute("Name") = "Beam";
  const glm::vec3 lens = profile.lensOffset;
  beam.append_attribute("Position") = position({lens.x, -lens.z, lens.y}).c_str();
  beam.append_attribute("BeamType") = "Wash";
  // A Beam is a cone: a distribution that lights more than a half space (a bare lamp's IES)
  // is written as the widest cone a reader takes, and the report says so.
  constexpr float kWidestConeDeg = 179.0f;
  const float beamDeg = std::min(angles.beamDeg(), kWidestConeDeg), fieldDeg = std::min(angles.fieldDeg(), kWidestConeDeg);
  if (fieldDeg < angles.fieldDeg())
    out.notCarried.push_back("the light beyond a cone of " + num(kWidestConeDeg) + " degrees (the distribution's field angle is " +
                             num(angles.fieldDeg()) + ")");
  beam.append_attribute("BeamAngle") = num(beamDeg).c_str();
  beam.append_attribute("FieldAngle") = num(fieldDeg).c_str();
  beam.append_attribute("LuminousFlux") = num(lumens).c_str();
  beam.append_attribute("BeamRadius") = num(profile.lensRadiusM).c_str();
  if (profile.photometrySource.kind != PhotometrySource::Kind::Parametric)
    out.notCarried.push_back("the measured intensity distribution: GDTF's Beam gives beam angle " + num(beamDeg) +
                             ", field angle " + num(fieldDeg) + " degrees and " + num(std::round(lumens)) +
                             " lm, from which a reader makes a smooth beam (peak " + num(std::round(profile.distribution->peakCd())) +
                             " cd here)");

  pugi::xml_node modes = ft.append_child("DMXModes");
  for (const DmxMode& m : profile.modes) {
    pugi::xml_node mode = modes.append_child("DMXMode");
    mode.append_attribute("Name") = m.name.c_str();
    mode.append_attribute("Geometry") = "Base";
    pugi::xml_node channels = mode.append_child("DMXChannels");
    for (std::size_t i = 0; i < m.channels.size(); ++i) {
      const DmxChannel& c = m.channels[i];
      if (c.byte != 0) continue;  // the fine bytes are offsets of their coarse one
      GdtfAttribute a = gdtfAttribute(c);
      if (a.name.empty()) a = {"NoFeature", "Control.Control"};
      const std::vector<std::size_t> slots = valueSlots(m, i);
      std::string offsets;
      for (std::size_t slot : slots) offsets += (offsets.empty() ? "" : ",") + std::to_string(slot + 1);
      pugi::xml_node ch = channels.append_child("DMXChannel");
      ch.append_attribute("DMXBreak") = 1;
      ch.append_attribute("Offset") = offsets.c_str();
      const bool onYoke = c.attribute == DmxAttribute::Pan;
      const bool onHead = c.attribute == DmxAttribute::Tilt;
      ch.append_attribute("Geometry") = onYoke ? "Yoke" : onHead ? "Head" : "Beam";
      pugi::xml_node logical = ch.append_child("LogicalChannel");
      logical.append_attribute("Attribute") = a.name.c_str();
      pugi::xml_node f = logical.append_child("ChannelFunction");
      f.append_attribute("Name") = (c.name.empty() ? a.name : c.name).c_str();
      f.append_attribute("Attribute") = a.name.c_str();
      f.append_attribute("DMXFrom") = ("0/" + std::to_string(slots.size())).c_str();
      f.append_attribute("PhysicalFrom") = num(c.physicalFrom).c_str();
      f.append_attribute("PhysicalTo") = num(c.physicalTo).c_str();
      if (c.attribute == DmxAttribute::Gobo || c.attribute == DmxAttribute::ColorWheel) {
        f.append_attribute("Wheel") = a.name.c_str();
        for (const DmxSlotRange& r : c.slotRanges) {
          pugi::xml_node set = f.append_child("ChannelSet");
          set.append_attribute("Name") = ("Slot " + std::to_string(r.slot + 1)).c_str();
          set.append_attribute("DMXFrom") = (std::to_string(r.from) + "/1").c_str();
          set.append_attribute("WheelSlotIndex") = r.slot + 1;
        }
      }
    }
  }
  if (profile.modes.empty()) {
    pugi::xml_node mode = modes.append_child("DMXMode");
    mode.append_attribute("Name") = "Default";
    mode.append_attribute("Geometry") = "Base";
    mode.append_child("DMXChannels");
  }
  if (unnamed) out.notCarried.push_back("channels of attributes haze names but this writer does not (blades, prisms, animation wheel, CTO), written as NoFeature");
  if (!profile.cells.empty()) out.notCarried.push_back("the cells of a multi-cell fixture (one Beam is written)");
  if (!profile.prisms.empty()) out.notCarried.push_back("the prisms' facets");
  if (profile.hasBlades) out.notCarried.push_back("the framing blades' geometry");
  bool shutterModes = false;
  for (const DmxMode& m : profile.modes)
    for (const DmxChannel& c : m.channels) shutterModes = shutterModes || !c.shutterRanges.empty() || !c.spinRanges.empty();
  if (shutterModes) out.notCarried.push_back("shutter (strobe) and spin ranges within a channel: each channel is one linear function");
  if (profile.zoomDeg.min < profile.zoomDeg.max)
    out.notCarried.push_back("the zoom's effect on the beam (the Zoom channel's range is written; the Beam has the profile's field angle)");

  std::ostringstream xml;
  doc.save(xml, "  ", pugi::format_default, pugi::encoding_utf8);
  const std::string text = xml.str();
  auto zip = zipToMemory({{"description.xml", std::vector<std::uint8_t>(text.begin(), text.end()), true}}, typeName + ".gdtf");
  if (!zip.ok()) return zip.error();
  out.bytes = std::move(*zip);
  return out;
}

}  // namespace haze
