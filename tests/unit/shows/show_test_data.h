// Shared by the shows unit tests: where the hand-built test shows are, loading them with their
// profiles, and a scratch folder per test.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "shows/playback.h"
#include "shows/show.h"

namespace haze::test {

inline std::filesystem::path showsDir() { return std::filesystem::path(HAZE_SOURCE_DIR) / "tests/data/shows"; }
inline std::filesystem::path validShowPath() { return showsDir() / "valid.haze.json"; }

struct LoadedShow {
  Show show;
  ProfileSet profiles;
  const CueList& main() const { return *show.findCueList("Main"); }
};

inline LoadedShow loadValidShow() {
  auto show = loadShow(validShowPath());
  if (!show) ADD_FAILURE() << show.error().str();
  if (!show) return {};
  auto profiles = loadProfiles(*show);
  if (!profiles) ADD_FAILURE() << profiles.error().str();
  if (!profiles) return {};
  return {std::move(*show), std::move(*profiles)};
}

// A fresh empty folder under the system temp folder, removed when the object goes.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path = std::filesystem::temp_directory_path() /
           ("haze-shows-" + std::string(info ? info->name() : "x") + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace haze::test
