// The desktop's own file dialog, as portable dialog libraries do it on Linux: `zenity
// --file-selection` (GNOME and most desktops) or `kdialog --getopenfilename` (KDE) as a child
// process whose answer is read without blocking the frame loop. When neither is on PATH, or
// HAZE_FILE_DIALOG=typed, the GUI asks for a typed path instead (gui_files.cpp).
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace haze {

class DesktopDialog {
 public:
  DesktopDialog() = default;
  DesktopDialog(const DesktopDialog&) = delete;
  DesktopDialog& operator=(const DesktopDialog&) = delete;
  ~DesktopDialog();  // a dialog still open is closed

  // Opens a dialog choosing one existing file, starting in `folder`, offering `patterns`
  // ("*.haze.json") under `filterName` and all files. False when no dialog program is there or
  // it could not be started.
  bool start(const std::string& title, const std::string& folder, const std::string& filterName,
             const std::vector<std::string>& patterns);
  bool running() const { return pid_ > 0; }

  enum class Outcome { Running, Chosen, Cancelled, Failed };
  // Chosen: `path` is the file. Failed: the program ended without an answer (no display...).
  Outcome poll(std::string& path);

 private:
  pid_t pid_ = -1;
  int out_ = -1;  // the child's stdout
  std::string answer_;
};

}  // namespace haze
