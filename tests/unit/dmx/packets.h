// Test helpers: Art-Net and sACN datagrams written field by field from the specifications
// (Art-Net 4 ArtDmx; E1.31-2018 table 4-1), independent of the parsers under test.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace haze::test {

struct ArtDmxFields {
  uint8_t sequence = 0;
  uint8_t physical = 0;
  uint8_t subUni = 0;
  uint8_t net = 0;
  std::vector<uint8_t> data = std::vector<uint8_t>(512, 0);
  int protVer = 14;
};

inline std::vector<uint8_t> artDmx(const ArtDmxFields& f) {
  std::vector<uint8_t> p(18 + f.data.size(), 0);
  const char id[8] = {'A', 'r', 't', '-', 'N', 'e', 't', 0};
  for (size_t i = 0; i < 8; ++i) p[i] = static_cast<uint8_t>(id[i]);
  p[8] = 0x00;  // OpDmx 0x5000, low byte first
  p[9] = 0x50;
  p[10] = static_cast<uint8_t>(f.protVer >> 8);
  p[11] = static_cast<uint8_t>(f.protVer);
  p[12] = f.sequence;
  p[13] = f.physical;
  p[14] = f.subUni;
  p[15] = f.net;
  p[16] = static_cast<uint8_t>(f.data.size() >> 8);
  p[17] = static_cast<uint8_t>(f.data.size());
  for (size_t i = 0; i < f.data.size(); ++i) p[18 + i] = f.data[i];
  return p;
}

struct SacnFields {
  uint8_t cidFill = 0x11;          // every CID byte
  std::string sourceName = "test console";
  uint8_t priority = 100;
  uint16_t syncAddress = 0;
  uint8_t sequence = 0;
  uint8_t options = 0;
  uint16_t universe = 1;
  uint8_t startCode = 0;
  std::vector<uint8_t> slots = std::vector<uint8_t>(512, 0);
};

inline void put16(std::vector<uint8_t>& p, size_t at, unsigned v) {
  p[at] = static_cast<uint8_t>(v >> 8);
  p[at + 1] = static_cast<uint8_t>(v);
}

inline std::vector<uint8_t> sacn(const SacnFields& f) {
  const size_t size = 126 + f.slots.size();
  std::vector<uint8_t> p(size, 0);
  put16(p, 0, 0x0010);
  put16(p, 2, 0x0000);
  const char id[12] = {'A', 'S', 'C', '-', 'E', '1', '.', '1', '7', 0, 0, 0};
  for (int i = 0; i < 12; ++i) p[4 + static_cast<size_t>(i)] = static_cast<uint8_t>(id[i]);
  put16(p, 16, 0x7000 | static_cast<unsigned>(size - 16));
  p[21] = 0x04;  // VECTOR_ROOT_E131_DATA
  for (size_t i = 22; i < 38; ++i) p[i] = f.cidFill;
  put16(p, 38, 0x7000 | static_cast<unsigned>(size - 38));
  p[43] = 0x02;  // VECTOR_E131_DATA_PACKET
  for (size_t i = 0; i < f.sourceName.size() && i < 63; ++i) p[44 + i] = static_cast<uint8_t>(f.sourceName[i]);
  p[108] = f.priority;
  put16(p, 109, f.syncAddress);
  p[111] = f.sequence;
  p[112] = f.options;
  put16(p, 113, f.universe);
  put16(p, 115, 0x7000 | static_cast<unsigned>(size - 115));
  p[117] = 0x02;  // VECTOR_DMP_SET_PROPERTY
  p[118] = 0xA1;
  put16(p, 119, 0x0000);
  put16(p, 121, 0x0001);
  put16(p, 123, static_cast<unsigned>(f.slots.size() + 1));
  p[125] = f.startCode;
  for (size_t i = 0; i < f.slots.size(); ++i) p[126 + i] = f.slots[i];
  return p;
}

// The E1.31 root layer (table 4-2/4-3 share it with data packets), vector EXTENDED (8).
inline void extendedRoot(std::vector<uint8_t>& p, uint8_t cidFill) {
  put16(p, 0, 0x0010);
  put16(p, 2, 0x0000);
  const char id[12] = {'A', 'S', 'C', '-', 'E', '1', '.', '1', '7', 0, 0, 0};
  for (int i = 0; i < 12; ++i) p[4 + static_cast<size_t>(i)] = static_cast<uint8_t>(id[i]);
  put16(p, 16, 0x7000 | static_cast<unsigned>(p.size() - 16));
  p[21] = 0x08;  // VECTOR_ROOT_E131_EXTENDED
  for (size_t i = 22; i < 38; ++i) p[i] = cidFill;
  put16(p, 38, 0x7000 | static_cast<unsigned>(p.size() - 38));
}

// E1.31 table 4-2: Synchronization Packet, 49 bytes.
inline std::vector<uint8_t> sacnSync(uint16_t syncAddress, uint8_t sequence = 0, uint8_t cidFill = 0x11) {
  std::vector<uint8_t> p(49, 0);
  extendedRoot(p, cidFill);
  p[43] = 0x01;  // VECTOR_E131_EXTENDED_SYNCHRONIZATION
  p[44] = sequence;
  put16(p, 45, syncAddress);
  return p;
}

// E1.31 table 4-3: Universe Discovery Packet, one page.
inline std::vector<uint8_t> sacnDiscovery(const std::vector<uint16_t>& universes, uint8_t page = 0,
                                          uint8_t lastPage = 0, const std::string& name = "test console",
                                          uint8_t cidFill = 0x11) {
  std::vector<uint8_t> p(120 + 2 * universes.size(), 0);
  extendedRoot(p, cidFill);
  p[43] = 0x02;  // VECTOR_E131_EXTENDED_DISCOVERY
  for (size_t i = 0; i < name.size() && i < 63; ++i) p[44 + i] = static_cast<uint8_t>(name[i]);
  put16(p, 112, 0x7000 | static_cast<unsigned>(p.size() - 112));
  p[117] = 0x01;  // VECTOR_UNIVERSE_DISCOVERY_UNIVERSE_LIST
  p[118] = page;
  p[119] = lastPage;
  for (size_t i = 0; i < universes.size(); ++i) put16(p, 120 + 2 * i, universes[i]);
  return p;
}

// Art-Net 4 ArtSync: ID, OpSync 0x5200 (low byte first), ProtVer 14, Aux1, Aux2.
inline std::vector<uint8_t> artSync() {
  std::vector<uint8_t> p = {'A', 'r', 't', '-', 'N', 'e', 't', 0, 0x00, 0x52, 0, 14, 0, 0};
  return p;
}

}  // namespace haze::test
