// The project's test data (venues, photometry, GDTF, MVR, gobos) for the C++ tests.
//
// Two places hold it: tests/data/shared, the files whose licence lets them travel with the
// repository (tests/data/shared/SOURCES.md names each one's origin and licence), and the full
// collection in ../shared/data beside the repository, which is optional. A file is taken from
// the repository first, so a test reads the same bytes with or without ../shared; a folder that
// a test walks whole is taken from ../shared/data when that is present (it holds more files).
// A test that needs a file neither place has skips with one line naming it: HAZE_NEED_DATA.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

namespace haze::test {

inline std::filesystem::path repoData() { return std::filesystem::path(HAZE_TEST_DATA); }
inline std::filesystem::path fullData() { return std::filesystem::path(HAZE_SHARED_DATA); }

// True when ../shared/data is beside the repository.
inline bool haveFullData() { return std::filesystem::is_directory(fullData()); }

// The file `relative` (to the data root, e.g. "photometry/ies/hydraapi/ies_34.ies"), or an empty
// path when neither place has it.
inline std::filesystem::path dataFile(std::string_view relative) {
  for (const std::filesystem::path& root : {repoData(), fullData()}) {
    std::filesystem::path p = root / relative;
    if (std::filesystem::exists(p)) return p;
  }
  return {};
}

// The folder `relative` to walk: ../shared/data's when present, else the repository's.
inline std::filesystem::path dataDir(std::string_view relative) {
  return haveFullData() ? fullData() / relative : repoData() / relative;
}

inline std::string missingData(std::string_view relative) {
  return "needs " + std::string(relative) + " from ../shared/data (not in this checkout; see README, Test data)";
}

}  // namespace haze::test

// Skips the running test, with one line naming the file, when the data does not have it.
#define HAZE_NEED_DATA(relative)                                                     \
  do {                                                                               \
    if (::haze::test::dataFile(relative).empty()) GTEST_SKIP() << ::haze::test::missingData(relative); \
  } while (0)
