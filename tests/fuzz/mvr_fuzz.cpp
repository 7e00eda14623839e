// Fuzz harness: an MVR archive's bytes through importMvr. The importer reads a file and writes
// a show next to it, so the bytes go through a private temporary folder. The venue is not
// built (writeVenue = false): that path hands the meshes to assimp, whose own parsers are not
// haze's to fuzz here.
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

#include "fuzz/harness.h"
#include "shows/import/mvr_import.h"

namespace haze::fuzz {
namespace {

// One folder per process, removed at exit: a passing run leaves nothing behind.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() : path(std::filesystem::temp_directory_path() / ("haze-fuzz-mvr-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace

bool acceptMvr(const uint8_t* data, size_t size) {
  static const ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path;
  const auto in = dir / "in.mvr";
  {
    std::ofstream out(in, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  std::error_code ec;
  std::filesystem::remove_all(dir / "out_gdtf", ec);
  auto r = importMvr(in, dir / "out.haze.json", MvrImportOptions{.writeVenue = false, .force = true});
  return r.ok();
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptMvr)
