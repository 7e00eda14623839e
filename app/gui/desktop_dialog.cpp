// DesktopDialog: posix_spawn with stdout on a non-blocking pipe and stderr to /dev/null (GTK's
// warnings are not ours to print); the exit status says chosen (0) or cancelled (1).
#include "app/gui/desktop_dialog.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

extern char** environ;

namespace haze {

namespace {

std::string onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  size_t from = 0;
  while (from <= dirs.size()) {
    size_t to = dirs.find(':', from);
    if (to == std::string::npos) to = dirs.size();
    const std::string candidate = (to > from ? dirs.substr(from, to - from) : std::string(".")) + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    from = to + 1;
  }
  return "";
}

}  // namespace

DesktopDialog::~DesktopDialog() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
  if (out_ >= 0) close(out_);
}

bool DesktopDialog::start(const std::string& title, const std::string& folder, const std::string& filterName,
                          const std::vector<std::string>& patterns) {
  if (running()) return false;
  const char* choice = std::getenv("HAZE_FILE_DIALOG");
  if (choice && std::string(choice) == "typed") return false;
  std::string joined;
  for (const std::string& p : patterns) joined += (joined.empty() ? "" : " ") + p;
  std::vector<std::string> args;
  std::string program = onPath("zenity");
  if (!program.empty()) {
    args = {program, "--file-selection", "--title=" + title, "--filename=" + folder + "/",
            "--file-filter=" + filterName + " | " + joined, "--file-filter=All files | *"};
  } else if (!(program = onPath("kdialog")).empty()) {
    args = {program, "--title", title, "--getopenfilename", folder, joined + "|" + filterName};
  } else {
    return false;
  }
  int pipeFds[2];
  if (pipe(pipeFds) != 0) return false;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipeFds[0]);
  posix_spawn_file_actions_addclose(&actions, pipeFds[1]);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipeFds[1]);
  if (rc != 0) {
    close(pipeFds[0]);
    return false;
  }
  fcntl(pipeFds[0], F_SETFL, fcntl(pipeFds[0], F_GETFL) | O_NONBLOCK);
  pid_ = pid;
  out_ = pipeFds[0];
  answer_.clear();
  return true;
}

DesktopDialog::Outcome DesktopDialog::poll(std::string& path) {
  if (!running()) return Outcome::Failed;
  char buf[4096];
  ssize_t n;
  while ((n = read(out_, buf, sizeof(buf))) > 0) answer_.append(buf, static_cast<size_t>(n));
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) != pid_) return Outcome::Running;
  while ((n = read(out_, buf, sizeof(buf))) > 0) answer_.append(buf, static_cast<size_t>(n));
  pid_ = -1;
  close(out_);
  out_ = -1;
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 1) return Outcome::Cancelled;
  const size_t end = answer_.find('\n');
  path = answer_.substr(0, end);
  if (code != 0 || path.empty()) return Outcome::Failed;
  return Outcome::Chosen;
}

}  // namespace haze
