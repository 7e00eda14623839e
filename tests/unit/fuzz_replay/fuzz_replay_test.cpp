// Replays every fuzz harness of tests/fuzz on its corpus (tests/fuzz/corpus/<parser>): the seeds
// must give their documented answer (ok-* accepted, bad-* refused), and a few thousand seeded
// mutations of them must neither crash nor throw. Under the ASan + UBSan build this is the
// fuzzers' regression run for machines without clang.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "fuzz/harness.h"

namespace haze {
namespace {

namespace fs = std::filesystem;
using Harness = bool (*)(const uint8_t*, size_t);

struct Seed {
  std::string name;
  std::vector<uint8_t> bytes;
};

std::vector<Seed> corpus(const std::string& parser) {
  std::vector<Seed> seeds;
  for (const auto& e : fs::directory_iterator(fs::path(HAZE_FUZZ_CORPUS) / parser)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    seeds.push_back({e.path().filename().string(),
                     std::vector<uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())});
  }
  std::sort(seeds.begin(), seeds.end(), [](const Seed& a, const Seed& b) { return a.name < b.name; });
  return seeds;
}

// Byte-level edits of the kinds that break parsers: flipped bits, boundary bytes, digits and
// signs in text, cut or repeated runs, and splices from another seed.
std::vector<uint8_t> mutate(std::vector<uint8_t> b, const std::vector<Seed>& seeds, std::mt19937& rng) {
  static const std::vector<std::string> tokens = {"0", "-1", "1e309", "nan", "4294967295", "18446744073709551604",
                                                  "\xff", "\xc3\x28", "\"", "{", "[", "]", "}", "\n", ",", "."};
  auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  const int edits = 1 + static_cast<int>(pick(4));
  for (int k = 0; k < edits; ++k) {
    const size_t at = b.empty() ? 0 : pick(b.size());
    switch (pick(7)) {
      case 0: if (!b.empty()) b[at] ^= static_cast<uint8_t>(1u << pick(8)); break;
      case 1: if (!b.empty()) b[at] = static_cast<uint8_t>(std::array<int, 6>{0, 1, 0x7f, 0x80, 0xfe, 0xff}[pick(6)]); break;
      case 2: {  // delete a run
        const size_t n = std::min(b.size() - at, pick(32) + 1);
        if (!b.empty()) b.erase(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
        break;
      }
      case 3: {  // insert a token
        const std::string& t = tokens[pick(tokens.size())];
        b.insert(b.begin() + static_cast<long>(at), t.begin(), t.end());
        break;
      }
      case 4: {  // repeat a run
        if (b.empty()) break;
        const size_t n = std::min(b.size() - at, pick(64) + 1);
        std::vector<uint8_t> run(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
        b.insert(b.begin() + static_cast<long>(at), run.begin(), run.end());
        break;
      }
      case 5: b.resize(at); break;  // truncate
      case 6: {  // splice the tail of another seed
        const Seed& other = seeds[pick(seeds.size())];
        if (other.bytes.empty()) break;
        const size_t from = pick(other.bytes.size());
        b.resize(at);
        b.insert(b.end(), other.bytes.begin() + static_cast<long>(from), other.bytes.end());
        break;
      }
    }
  }
  return b;
}

// The mutation count is fixed (deterministic); the time cap only guards a slow machine, and
// is reported when it cuts the run short.
void replay(const std::string& parser, Harness harness, int mutations, unsigned seed) {
  const std::vector<Seed> seeds = corpus(parser);
  ASSERT_FALSE(seeds.empty()) << "no corpus in tests/fuzz/corpus/" << parser;
  int ok = 0, bad = 0;
  for (const Seed& s : seeds) {
    bool accepted = false;
    try {
      accepted = harness(s.bytes.data(), s.bytes.size());
    } catch (const std::exception& e) {
      ADD_FAILURE() << parser << "/" << s.name << " threw: " << e.what();
      continue;
    }
    if (s.name.rfind("ok-", 0) == 0) {
      EXPECT_TRUE(accepted) << parser << "/" << s.name << " is a valid seed and was refused";
      ++ok;
    } else if (s.name.rfind("bad-", 0) == 0) {
      EXPECT_FALSE(accepted) << parser << "/" << s.name << " is a broken seed and was accepted";
      ++bad;
    }
  }
  EXPECT_GT(ok, 0) << "the corpus needs a valid seed (ok-*) for mutations to reach deep code";
  std::mt19937 rng(seed);
  const auto start = std::chrono::steady_clock::now();
  int run = 0, accepted = 0;
  for (; run < mutations; ++run) {
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(10)) {
      std::cout << parser << ": time cap after " << run << " of " << mutations << " mutations\n";
      break;
    }
    const Seed& base = seeds[static_cast<size_t>(run) % seeds.size()];
    const std::vector<uint8_t> input = mutate(base.bytes, seeds, rng);
    try {
      accepted += harness(input.data(), input.size()) ? 1 : 0;
    } catch (const std::exception& e) {
      ADD_FAILURE() << parser << ": mutation " << run << " of " << base.name << " threw: " << e.what();
      return;
    }
  }
  std::cout << parser << ": " << seeds.size() << " seeds, " << run << " mutations, " << accepted << " accepted\n";
}

TEST(FuzzReplay, Ies) { replay("ies", fuzz::acceptIes, 3000, 1); }
TEST(FuzzReplay, Ldt) { replay("ldt", fuzz::acceptLdt, 3000, 2); }
TEST(FuzzReplay, ProfileJson) { replay("profile_json", fuzz::acceptProfileJson, 3000, 3); }
TEST(FuzzReplay, Show) { replay("show", fuzz::acceptShow, 2000, 4); }
TEST(FuzzReplay, Venue) { replay("venue", fuzz::acceptVenue, 3000, 5); }
TEST(FuzzReplay, Gdtf) { replay("gdtf", fuzz::acceptGdtf, 1000, 6); }
TEST(FuzzReplay, GdtfXml) { replay("gdtf_xml", fuzz::acceptGdtfXml, 1500, 10); }
TEST(FuzzReplay, Mvr) { replay("mvr", fuzz::acceptMvr, 300, 7); }
TEST(FuzzReplay, ArtNet) { replay("artnet", fuzz::acceptArtNet, 5000, 8); }
TEST(FuzzReplay, Sacn) { replay("sacn", fuzz::acceptSacn, 5000, 9); }
TEST(FuzzReplay, SacnExtended) { replay("sacn_extended", fuzz::acceptSacnExtended, 5000, 11); }
TEST(FuzzReplay, ArtTimeCode) { replay("artnet_timecode", fuzz::acceptArtTimeCode, 3000, 12); }
TEST(FuzzReplay, Osc) { replay("osc", fuzz::acceptOsc, 5000, 13); }
TEST(FuzzReplay, MidiTimecode) { replay("midi_timecode", fuzz::acceptMidiTimecode, 5000, 14); }
TEST(FuzzReplay, Mesh) { replay("mesh", fuzz::acceptMesh, 500, 15); }
TEST(FuzzReplay, Qxf) { replay("qxf", fuzz::acceptQxf, 3000, 16); }
// Fewer: each accepted input is a 512-pixel raster (a few ms).
TEST(FuzzReplay, SvgGobo) { replay("svg_gobo", fuzz::acceptSvgGobo, 600, 17); }
TEST(FuzzReplay, Xchange) { replay("xchange", fuzz::acceptXchange, 3000, 18); }

}  // namespace
}  // namespace haze
