// A haze profile that is not a GDTF file (native JSON, IES, EULUMDAT) written as a minimal GDTF,
// so an MVR export can name a GDTFSpec for its fixtures: the fixture type, a Base > Yoke > Head
// > Beam geometry with the beam's angles, flux and lens, the colour and gobo wheels' slots, and
// every DMX mode with its channels. What GDTF cannot carry from the profile is listed
// (docs/mvr.md, "Export").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "fixtures/profile.h"

namespace haze {

struct GdtfWrite {
  std::vector<std::uint8_t> bytes;      // the .gdtf archive (description.xml)
  std::vector<std::string> notCarried;  // one line each: what the GDTF leaves out
};

// typeName: the FixtureType's Name (the show's profile key); fixtureTypeId: its uuid.
Result<GdtfWrite> profileToGdtf(const Profile& profile, const std::string& typeName, const std::string& fixtureTypeId);

}  // namespace haze
