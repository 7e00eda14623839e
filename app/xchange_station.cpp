#include "app/xchange_station.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <mutex>
#include <thread>

#include "fixtures/core/atomic_file.h"
#include "shows/import/mvr_export.h"
#include "shows/import/mvr_import.h"
#include "shows/show.h"
#include "shows/xchange/mdns.h"
#include "shows/xchange/tcp.h"

namespace haze {

namespace fs = std::filesystem;
using namespace haze::xchange;

void addXchangeOptions(CommandLine& cli, XchangeOptions& o) {
  cli.flag("--mvr-xchange", o.enabled)
      .text("--group", o.group, "an MVR-xchange group name")
      .integer("--mvr-xchange-port", o.port, 0, 65535, "a port 0..65535")
      .custom("--mvr-xchange-peer", "HOST:PORT with an IPv4 address", [&o](const std::string& v) {
        if (!parseEndpoint(v)) return false;
        o.peers.push_back(v);
        return true;
      })
      .text("--accept-commits", o.acceptDir, "a folder for the shows other stations commit")
      .text("--station-name", o.stationName, "a name for this station");
}

namespace {

double nowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The lines also go to the GUI's window: the last 50 are kept.
std::mutex gLinesMutex;
std::deque<std::string> gLines;

void say(const std::string& line) {
  std::fprintf(stderr, "haze live: MVR-xchange: %s\n", line.c_str());
  std::lock_guard<std::mutex> lock(gLinesMutex);
  gLines.push_back(line);
  if (gLines.size() > 50) gLines.pop_front();
}

// The station's uuid stays the same across start-ups (the specification asks for it): kept in
// $XDG_CONFIG_HOME/haze/mvr-xchange-station (or ~/.config/haze/...). A new one when unreadable.
std::string stationUuid() {
  fs::path dir;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) dir = fs::path(xdg) / "haze";
  else if (const char* home = std::getenv("HOME"); home && *home) dir = fs::path(home) / ".config" / "haze";
  const fs::path file = dir / "mvr-xchange-station";
  if (!dir.empty()) {
    std::ifstream in(file);
    std::string text;
    if (in >> text && !normaliseUuid(text).empty()) return normaliseUuid(text);
  }
  const std::string made = makeMvrUuid();
  std::error_code ec;
  if (!dir.empty()) {
    fs::create_directories(dir, ec);
    if (!ec) (void)writeFileAtomically(file, made + "\n", false);
  }
  return made;
}

std::string hostName() {
  char name[256] = {};
  return gethostname(name, sizeof name - 1) == 0 && name[0] ? name : "this machine";
}

struct ShowStamp {
  fs::file_time_type time{};
  std::uintmax_t size = 0;
  bool operator==(const ShowStamp&) const = default;
};

ShowStamp stampOf(const fs::path& file) {
  std::error_code ec;
  ShowStamp s;
  s.time = fs::last_write_time(file, ec);
  s.size = fs::file_size(file, ec);
  return s;
}

// A file name for a received show: the commit's FileName reduced to letters, digits, '-' and
// '_' (never a path), or the file's uuid; "-2", "-3"... when DIR has it already.
fs::path freeShowName(const fs::path& dir, const CommitInfo& c) {
  std::string stem;
  for (char ch : fs::path(c.fileName).stem().string().substr(0, 64))
    if (std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_') stem += ch;
  if (stem.empty()) stem = "xchange-" + c.fileUuid.substr(0, 8);
  for (int k = 1; k < 1000; ++k) {
    const std::string name = k == 1 ? stem : stem + "-" + std::to_string(k);
    std::error_code ec;
    if (!fs::exists(dir / (name + ".haze.json"), ec) && !fs::exists(dir / (name + "_gdtf"), ec) &&
        !fs::exists(dir / (name + "_source.mvr"), ec))
      return dir / (name + ".haze.json");
  }
  return dir / ("xchange-" + c.fileUuid + ".haze.json");
}

}  // namespace

struct XchangeService::Impl {
  fs::path showFile, acceptDir, work;  // work: the exported and received files, removed at the end
  XchangeOptions options;
  Station station;
  std::unique_ptr<Node> node;
  std::unique_ptr<Mdns> mdns;
  std::vector<Endpoint> peers;
  std::deque<fs::path> exported;  // the files of the offered commits, oldest first
  ShowStamp stamp;
  double stampChangedAt = 0.0;
  std::atomic<bool> stop{false};
  std::thread thread;
  // Between the station's thread and the GUI: what it sees, what the GUI asks for.
  mutable std::mutex mutex;
  std::vector<XchangeService::StationSeen> seen;
  bool commitAsked = false;
  std::vector<std::string> requestsAsked;

  explicit Impl(Identity id) : station(std::move(id)) {}
  Result<CommitInfo> exportShow(const std::string& comment);
  void offerShow(const std::string& comment, bool announce);
  void importFile(ReceivedFile&& f);
  void watchShow(double now);
  void serveAsks();
  void publishSeen();
  void run();
};

Result<CommitInfo> XchangeService::Impl::exportShow(const std::string& comment) {
  // From the file on disk, not the live show: what the user saved is what the group gets.
  // Fixtures without a uuid get one in this export only (`haze export-mvr` saves them).
  Result<Show> show = loadShow(showFile);
  if (!show) return show.error();
  CommitInfo c;
  c.fileUuid = makeMvrUuid();
  const fs::path file = work / (c.fileUuid + ".mvr");
  MvrExportOptions o;
  o.force = true;
  Result<MvrExport> out = exportMvr(*show, file, o);
  if (!out) return out.error();
  std::error_code ec;
  c.fileSize = fs::file_size(file, ec);
  c.fileName = showFile.filename().string();
  if (const auto dot = c.fileName.find('.'); dot != std::string::npos) c.fileName = c.fileName.substr(0, dot);
  c.fileName += ".mvr";
  c.comment = comment;
  if (std::sscanf(out->version.c_str(), "%d.%d", &c.verMajor, &c.verMinor) != 2) c.verMajor = 1, c.verMinor = 6;
  exported.push_back(file);
  return c;
}

void XchangeService::Impl::offerShow(const std::string& comment, bool announce) {
  Result<CommitInfo> c = exportShow(comment);
  if (!c) return say(showFile.string() + ": not offered: " + c.error().str());
  const CommitInfo offered = station.offer(*c);
  while (exported.size() > station.offered().size()) {  // the station keeps the latest few
    std::error_code ec;
    fs::remove(exported.front(), ec);
    exported.pop_front();
  }
  const int sent = announce ? node->sendToJoined(station.commit(offered)) : 0;
  say("offering " + showFile.filename().string() + " as file " + offered.fileUuid + " (" + std::to_string(offered.fileSize) +
      " bytes)" + (announce ? ", MVR_COMMIT sent to " + std::to_string(sent) + " station" + (sent == 1 ? "" : "s") : ""));
}

// The show file changed on disk: once it has held still for half a second (a save is done), a
// new export becomes a commit.
void XchangeService::Impl::watchShow(double now) {
  const ShowStamp s = stampOf(showFile);
  if (s == stamp) {
    if (stampChangedAt > 0 && now - stampChangedAt >= 0.5) {
      stampChangedAt = 0;
      offerShow("saved in haze", true);
    }
    return;
  }
  stamp = s;
  stampChangedAt = now;
}

// Into a folder of its own inside DIR first (so the moves are renames on one file system), then
// moved into DIR: a failed import leaves nothing in DIR.
void XchangeService::Impl::importFile(ReceivedFile&& f) {
  if (acceptDir.empty()) return;
  const fs::path mvr = work / ("received-" + f.commit.fileUuid + ".mvr");
  if (Status s = writeFileAtomically(mvr, std::string_view(reinterpret_cast<const char*>(f.bytes.data()), f.bytes.size()), false);
      !s)
    return say(s.error().str());
  const fs::path target = freeShowName(acceptDir, f.commit);
  const fs::path stage = acceptDir / (".haze-xchange-import-" + f.commit.fileUuid);
  std::error_code ec;
  fs::remove_all(stage, ec);
  fs::create_directories(stage, ec);
  Result<MvrImport> in = importMvr(mvr, stage / target.filename());
  fs::remove(mvr, ec);
  if (!in) {
    fs::remove_all(stage, ec);
    return say("file " + f.commit.fileUuid + " not imported: " + in.error().str());
  }
  for (const auto& e : fs::directory_iterator(stage, ec)) {
    fs::rename(e.path(), acceptDir / e.path().filename(), ec);
    if (ec) {
      std::error_code ignored;
      fs::remove_all(stage, ignored);
      return say("file " + f.commit.fileUuid + ": moving " + e.path().filename().string() + " into " +
                 acceptDir.string() + " failed: " + ec.message());
    }
  }
  fs::remove_all(stage, ec);
  say("imported file " + f.commit.fileUuid + " as " + target.string() + " (" + std::to_string(in->fixtureCount) + " fixtures)");
}

void XchangeService::Impl::serveAsks() {
  bool commit = false;
  std::vector<std::string> asked;
  {
    std::lock_guard<std::mutex> lock(mutex);
    std::swap(commit, commitAsked);
    asked.swap(requestsAsked);
  }
  if (commit) offerShow("committed from haze's window", true);
  for (const std::string& uuid : asked) {
    const ConnectionId c = node->connectionOf(uuid);
    if (c == 0) {
      say("station " + uuid + " is not connected; nothing requested");
      continue;
    }
    node->send(c, station.request(c, "", uuid));
    say("MVR_REQUEST for the latest file of " + uuid);
  }
}

void XchangeService::Impl::publishSeen() {
  std::vector<XchangeService::StationSeen> now;
  for (const auto& [uuid, p] : station.peers()) {
    XchangeService::StationSeen s;
    s.name = p.name;
    s.uuid = uuid;
    s.provider = p.provider;
    s.files = p.commits.size();
    if (!p.commits.empty()) s.latestFile = p.commits.back().fileUuid;
    s.connected = node->connectionOf(uuid) != 0;
    s.left = p.left;
    now.push_back(std::move(s));
  }
  std::lock_guard<std::mutex> lock(mutex);
  seen.swap(now);
}

void XchangeService::Impl::run() {
  double nextDial = 0.0;
  stamp = stampOf(showFile);
  while (!stop) {
    node->pump(100);
    serveAsks();
    publishSeen();
    const double now = nowS();
    if (mdns) {
      for (const std::string& n : mdns->takeNotes()) say(n);
      for (const Discovered& d : mdns->pump()) {
        if (node->dialled(d.endpoint)) continue;
        say("found \"" + d.name + "\" (" + d.uuid + ") at " + d.endpoint.str() + " by mDNS");
        if (Result<ConnectionId> c = node->dial(d.endpoint, station.join()); !c) say(c.error().str());
      }
    }
    if (now >= nextDial) {  // direct peers: dialled again every 5 s while not connected
      nextDial = now + 5.0;
      for (const Endpoint& e : peers)
        if (!node->dialled(e))
          if (Result<ConnectionId> c = node->dial(e, station.join()); !c) say(c.error().str());
    }
    watchShow(now);
  }
  const int left = node->sendToJoined(station.leave());
  if (left > 0) say("MVR_LEAVE sent to " + std::to_string(left) + " station" + (left == 1 ? "" : "s"));
  node->flushAndClose(1000);
}

Result<std::unique_ptr<XchangeService>> XchangeService::start(const fs::path& showFile, const std::string& bindAddress,
                                                              const XchangeOptions& options) {
  if (options.group.empty() || options.group.size() > 40 || options.group.find_first_of("@.") != std::string::npos)
    return Error{"", "", "--group '" + options.group + "' is not a group name (1..40 characters, no '@' or '.')"};
  Identity id;
  id.name = options.stationName.empty() ? "haze on " + hostName() : options.stationName;
  id.uuid = stationUuid();
  std::unique_ptr<XchangeService> service(new XchangeService());
  service->impl_ = std::make_unique<Impl>(id);
  Impl& s = *service->impl_;
  s.showFile = showFile;
  s.options = options;
  s.station.setRequestCommits(!options.acceptDir.empty() && options.requestCommits);
  if (!options.acceptDir.empty()) {
    s.acceptDir = options.acceptDir;
    std::error_code ec;
    if (!fs::is_directory(s.acceptDir, ec))
      return Error{options.acceptDir, "", "--accept-commits needs an existing folder"};
  }
  for (const std::string& p : options.peers) s.peers.push_back(*parseEndpoint(p));
  char tmpl[] = "/tmp/haze-xchange-XXXXXX";
  if (!mkdtemp(tmpl)) return Error{"", "", "MVR-xchange: no temporary folder"};
  s.work = tmpl;
  NodeHooks hooks;
  hooks.log = say;
  hooks.fileBytes = [&s](const CommitInfo& c) -> Result<std::vector<std::uint8_t>> {
    const fs::path file = s.work / (c.fileUuid + ".mvr");
    std::ifstream in(file, std::ios::binary);
    if (!in) return Error{file.string(), "", "the exported MVR is gone"};
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  hooks.received = [&s](ReceivedFile&& f) { s.importFile(std::move(f)); };
  Result<std::unique_ptr<Node>> node = Node::listen(bindAddress, options.port, s.station, hooks);
  if (!node) return node.error();
  s.node = std::move(*node);
  s.offerShow("the show as haze opened it", false);
  if (Result<std::unique_ptr<Mdns>> m = Mdns::start(id, options.group, s.node->port()); m) s.mdns = std::move(*m);
  else say(m.error().str() + "; stations are reached only by --mvr-xchange-peer HOST:PORT");
  // Last, once haze is ready; the form of the other listeners' lines ("haze live: OSC on ADDR:PORT"), which tests read.
  std::fprintf(stderr, "haze live: MVR-xchange on %s:%d (station \"%s\", %s, group %s)\n", bindAddress.c_str(),
               s.node->port(), id.name.c_str(), id.uuid.c_str(), options.group.c_str());
  s.thread = std::thread([&s] { s.run(); });
  return service;
}

std::vector<XchangeService::StationSeen> XchangeService::stations() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->seen;
}

int XchangeService::port() const { return impl_->node->port(); }

void XchangeService::commitNow() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->commitAsked = true;
}

void XchangeService::request(const std::string& stationUuid) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  if (impl_->requestsAsked.size() < 64) impl_->requestsAsked.push_back(stationUuid);
}

std::vector<std::string> XchangeService::recentLines() const {
  std::lock_guard<std::mutex> lock(gLinesMutex);
  return std::vector<std::string>(gLines.begin(), gLines.end());
}

XchangeService::~XchangeService() {
  if (!impl_) return;
  impl_->stop = true;
  if (impl_->thread.joinable()) impl_->thread.join();
  impl_->node.reset();
  std::error_code ec;
  if (!impl_->work.empty()) fs::remove_all(impl_->work, ec);
}

}  // namespace haze
