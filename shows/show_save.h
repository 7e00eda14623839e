// Saving that never loses a show: the new text goes to a temporary file in the same folder, is
// flushed to disk (file and folder), and renamed over the show, so a crash at any moment leaves
// the old show or the new one, never a mix. The previous version stays as SHOW.bak (for
// demo.haze.json: demo.haze.json.bak). A save refuses to overwrite a file that changed on disk
// since the show was loaded or last saved, unless forced.
#pragma once

#include <filesystem>
#include <string_view>

#include "fixtures/core/atomic_file.h"
#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

struct SaveOptions {
  bool force = false;       // overwrite even if the file changed on disk (or is another show)
  bool keepBackup = true;   // keep the version being replaced as backupPathFor(file)
};

// Writes the show to `file` (docs/show-format.md text). On success show.file and show.stamp describe
// the new file, so the next save checks against it.
Status saveShow(Show& show, const std::filesystem::path& file, const SaveOptions& options = {});

}  // namespace haze
