// Recent files (see recent_files.h).
#include "shows/edit/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "shows/show_save.h"

namespace haze {

namespace fs = std::filesystem;

fs::path recentFilesPath() {
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return fs::path(x) / "haze" / "recent.txt";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".config" / "haze" / "recent.txt";
  return {};
}

std::vector<std::string> loadRecentFiles(const fs::path& listFile) {
  std::vector<std::string> out;
  if (listFile.empty()) return out;
  std::ifstream in(listFile);
  std::string line;
  while (out.size() < kMaxRecentFiles && std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && std::find(out.begin(), out.end(), line) == out.end()) out.push_back(line);
  }
  return out;
}

std::vector<std::string> withRecentFile(std::vector<std::string> recent, const fs::path& show) {
  std::error_code ec;
  const std::string path = fs::absolute(show, ec).lexically_normal().string();
  std::erase(recent, path);
  recent.insert(recent.begin(), path);
  if (recent.size() > kMaxRecentFiles) recent.resize(kMaxRecentFiles);
  return recent;
}

Status saveRecentFiles(const fs::path& listFile, const std::vector<std::string>& recent) {
  if (listFile.empty()) return Error{"", "recent files", "neither XDG_CONFIG_HOME nor HOME is set"};
  std::error_code ec;
  fs::create_directories(listFile.parent_path(), ec);
  if (ec) return Error{listFile.parent_path().string(), "", "cannot create the folder: " + ec.message()};
  std::string text;
  for (const std::string& r : recent) text += r + "\n";
  return writeFileAtomically(listFile, text, false);
}

}  // namespace haze
