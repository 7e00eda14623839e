// Test helper: writes small zip archives with libzip (the synthetic good and bad GDTF files of
// these tests) into a temporary folder that is removed afterwards.
#pragma once

#include <unistd.h>
#include <zip.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace haze::test {

struct ZipItem {
  std::string name;
  std::string data;
  bool store = false;  // true: no compression
};

// Writes `items` into `path`; returns false when libzip refuses.
inline bool writeZip(const std::filesystem::path& path, const std::vector<ZipItem>& items) {
  int err = 0;
  zip_t* z = zip_open(path.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
  if (!z) return false;
  for (const ZipItem& item : items) {
    // libzip copies nothing until zip_close: keep the data alive by letting it own a copy.
    void* copy = item.data.empty() ? nullptr : std::malloc(item.data.size());
    if (copy) std::memcpy(copy, item.data.data(), item.data.size());
    zip_source_t* s = zip_source_buffer(z, copy, item.data.size(), 1);
    if (!s) {
      zip_discard(z);
      return false;
    }
    zip_int64_t idx = zip_file_add(z, item.name.c_str(), s, ZIP_FL_OVERWRITE | ZIP_FL_ENC_UTF_8);
    if (idx < 0) {
      zip_source_free(s);
      zip_discard(z);
      return false;
    }
    zip_set_file_compression(z, static_cast<zip_uint64_t>(idx), item.store ? ZIP_CM_STORE : ZIP_CM_DEFLATE, 9);
  }
  return zip_close(z) == 0;
}

inline std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeFile(const std::filesystem::path& p, const std::string& data) {
  std::ofstream out(p, std::ios::binary);
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
}

// A folder under the system temp dir, unique per test, removed when the object dies.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    path_ = std::filesystem::temp_directory_path() /
            ("haze-gdtf-" + tag + "-" + std::to_string(::getpid()) + "-" +
             std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace haze::test
