// Atomic, durable show saving with POSIX calls (see show_save.h). Order of a save:
//   1. write the new bytes to .NAME.tmp-PID-N beside the show, fsync it;
//   2. hard-link the current show to .NAME.bak.tmp-PID-N and rename that over NAME.bak (the
//      show itself is never touched, so a crash here loses nothing);
//   3. rename the temporary file over NAME (atomic: readers see old or new), fsync the folder.
// A temporary name carries the writer's PID, so later saves can remove the leftovers of a
// writer that was killed, without touching those of one still running.
#include "shows/show_save.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <optional>
#include <string>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shows/show_json.h"

namespace haze {

namespace {

namespace fs = std::filesystem;

std::atomic<unsigned> gSaveCounter{0};

std::string errnoText(int e) { return std::strerror(e); }

Error saveError(const fs::path& file, const std::string& what) {
  return Error{file.string(), "", "cannot save the show: " + what};
}

bool writeAll(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

// Writes bytes to a fresh file `path` (must not exist) and fsyncs it; errno is kept on failure.
bool writeNewFile(const fs::path& path, std::string_view bytes, mode_t mode) {
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
  if (fd < 0) return false;
  bool ok = writeAll(fd, bytes) && ::fsync(fd) == 0;
  int saved = errno;
  ::close(fd);
  errno = saved;
  if (!ok) ::unlink(path.c_str());
  return ok;
}

bool fsyncFolder(const fs::path& dir) {
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

// ".NAME.tmp-PID-N" and ".NAME.bak.tmp-PID-N": the PID of a leftover, or 0 when not one.
pid_t leftoverPid(const std::string& entry, const std::string& name) {
  for (const std::string& prefix : {"." + name + ".tmp-", "." + name + ".bak.tmp-"}) {
    if (entry.rfind(prefix, 0) != 0) continue;
    long pid = std::strtol(entry.c_str() + prefix.size(), nullptr, 10);
    return pid > 0 ? static_cast<pid_t>(pid) : 0;
  }
  return 0;
}

void removeLeftovers(const fs::path& dir, const std::string& name) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    pid_t pid = leftoverPid(it->path().filename().string(), name);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(pid, 0) != 0 && errno == ESRCH) {
      std::error_code rmEc;
      fs::remove(it->path(), rmEc);
    }
  }
}

std::string tempName(const std::string& stem) {
  return "." + stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(gSaveCounter++);
}

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

fs::path backupPathFor(const fs::path& file) {
  fs::path b = file;
  b += ".bak";
  return b;
}

Status writeFileAtomically(const fs::path& file, std::string_view bytes, bool keepBackup) {
  if (file.filename().empty()) return saveError(file, "expected a file name, got a folder");
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  const std::string name = file.filename().string();
  removeLeftovers(dir, name);

  struct stat old {};
  bool exists = ::stat(file.c_str(), &old) == 0;
  if (exists && !S_ISREG(old.st_mode)) return saveError(file, "it exists and is not a regular file");
  mode_t mode = exists ? (old.st_mode & 07777) : 0644;

  const fs::path tmp = dir / tempName(name);
  if (!writeNewFile(tmp, bytes, mode))
    return saveError(file, "writing " + tmp.string() + " failed: " + errnoText(errno));
  // open() applied the umask; give the new file the old one's permissions.
  if (exists) ::chmod(tmp.c_str(), mode);

  if (exists && keepBackup) {
    const fs::path bakTmp = dir / tempName(name + ".bak");
    bool linked = ::link(file.c_str(), bakTmp.c_str()) == 0;
    if (!linked) {
      // No hard links here (some network and FAT file systems): copy the old bytes instead.
      auto oldBytes = readShowBytes(file);
      linked = oldBytes.ok() && writeNewFile(bakTmp, *oldBytes, mode);
    }
    if (!linked || ::rename(bakTmp.c_str(), backupPathFor(file).c_str()) != 0) {
      int e = errno;
      ::unlink(bakTmp.c_str());
      ::unlink(tmp.c_str());
      return saveError(file, "keeping the backup " + backupPathFor(file).string() + " failed: " + errnoText(e));
    }
  }
  if (::rename(tmp.c_str(), file.c_str()) != 0) {
    int e = errno;
    ::unlink(tmp.c_str());
    return saveError(file, "renaming " + tmp.string() + " over it failed: " + errnoText(e));
  }
  if (!fsyncFolder(dir)) return saveError(file, "flushing the folder " + dir.string() + " failed: " + errnoText(errno));
  return Ok{};
}

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
    for (auto& [name, ref] : moved->profiles)
      if (!ref.inlineObject) ref.path = rebase(ref.path, oldDir, newDir);
  }
  const std::string text = showToText(moved ? *moved : show);
  Status written = writeFileAtomically(file, text, options.keepBackup);
  if (!written) return written;
  if (moved) {
    show.venueGltf = moved->venueGltf;
    show.profiles = std::move(moved->profiles);
  }
  show.file = file;
  show.stamp = stampOf(text);
  return Ok{};
}

}  // namespace haze
