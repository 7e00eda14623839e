// The recently opened shows, newest first, kept in $XDG_CONFIG_HOME/haze/recent.txt (or
// ~/.config/haze/recent.txt): one absolute path a line. A missing or unreadable list is an empty
// one; the GUI shows a failed write in its status line and carries on.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fixtures/core/result.h"

namespace haze {

inline constexpr size_t kMaxRecentFiles = 10;

// Where the list lives: from XDG_CONFIG_HOME, else HOME; empty when neither is set.
std::filesystem::path recentFilesPath();
std::vector<std::string> loadRecentFiles(const std::filesystem::path& listFile);
// Moves (or adds) `show` to the front, drops the oldest beyond kMaxRecentFiles.
std::vector<std::string> withRecentFile(std::vector<std::string> recent, const std::filesystem::path& show);
// Written atomically (temporary file and rename), the folder created when missing.
Status saveRecentFiles(const std::filesystem::path& listFile, const std::vector<std::string>& recent);

}  // namespace haze
