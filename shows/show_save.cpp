// Show saving (see show_save.h): the guards against overwriting someone else's edits and the
// rebasing of relative paths; the atomic replacement itself is fixtures/core/atomic_file.
#include "shows/show_save.h"

#include <optional>
#include <string>

#include "shows/show_json.h"

namespace haze {

namespace {

namespace fs = std::filesystem;

// Relative paths inside a show are relative to its folder; saving into another folder rewrites
// them so they still name the same files. Absolute paths stay as they are.
std::string rebase(const std::string& relative, const fs::path& oldDir, const fs::path& newDir) {
  fs::path p(relative);
  if (relative.empty() || p.is_absolute()) return relative;
  std::error_code ec;
  fs::path target = fs::absolute(oldDir / p, ec).lexically_normal();
  fs::path rebased = target.lexically_relative(fs::absolute(newDir, ec).lexically_normal());
  return rebased.empty() ? target.string() : rebased.generic_string();
}

}  // namespace

Status saveShow(Show& show, const fs::path& file, const SaveOptions& options) {
  std::error_code ec;
  if (!options.force && fs::exists(file, ec)) {
    bool sameFile = !show.file.empty() && fs::exists(show.file, ec) && fs::equivalent(show.file, file, ec);
    if (!sameFile || !show.stamp)
      return Error{file.string(), "", "will not overwrite an existing file that this show was not loaded from; "
                                      "save with force to replace it"};
    auto current = readShowBytes(file);
    if (!current) return current.error();
    if (stampOf(*current) != *show.stamp)
      return Error{file.string(), "", "the file changed on disk since the show was loaded (edited elsewhere?); "
                                      "reload it, or save with force to overwrite those changes"};
  }
  // Saving into another folder: relative paths are rewritten to name the same files from there.
  std::optional<Show> moved;
  const fs::path oldDir = show.file.parent_path(), newDir = file.parent_path();
  if (!show.file.empty() && fs::absolute(oldDir, ec).lexically_normal() != fs::absolute(newDir, ec).lexically_normal()) {
    moved = show;
    moved->venueGltf = rebase(show.venueGltf, oldDir, newDir);
    moved->mvrSource = rebase(show.mvrSource, oldDir, newDir);
    for (auto& [name, ref] : moved->profiles)
      if (!ref.inlineObject) ref.path = rebase(ref.path, oldDir, newDir);
  }
  const std::string text = showToText(moved ? *moved : show);
  Status written = writeFileAtomically(file, text, options.keepBackup);
  if (!written) return written;
  if (moved) {
    show.venueGltf = moved->venueGltf;
    show.mvrSource = moved->mvrSource;
    show.profiles = std::move(moved->profiles);
  }
  show.file = file;
  show.stamp = stampOf(text);
  return Ok{};
}

}  // namespace haze
