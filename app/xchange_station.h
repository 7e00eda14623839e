// `haze live SHOW --mvr-xchange`: haze as an MVR-xchange station (docs/mvr.md, "MVR-xchange")
// beside the live loop, in a thread of its own. It announces itself over mDNS (when an Avahi
// daemon is there) and dials the --mvr-xchange-peer addresses, answers JOIN and REQUEST with the
// show exported as MVR, sends a COMMIT when the show file changes on disk, and with
// --accept-commits DIR fetches what other stations commit and imports it into a new show in DIR.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/command_line.h"

namespace haze {

struct XchangeOptions {
  bool enabled = false;
  std::string group = "Default";
  int port = 0;                      // 0: a free port (announced over mDNS, printed)
  std::vector<std::string> peers;    // HOST:PORT, dialled directly
  std::string acceptDir;             // "" = commits are listed, not fetched
  std::string stationName;           // "" = "haze on HOSTNAME"
  bool requestCommits = true;        // with acceptDir: fetch every commit (false: only request())
};

// The options' declarations, for `haze live`'s command line.
void addXchangeOptions(CommandLine& cli, XchangeOptions& options);

class XchangeService {
 public:
  // Exports the show once, listens on bindAddress, starts the station's thread; an Error when
  // the port cannot be had or the options are wrong. mDNS that cannot start is one line, not an
  // error.
  static Result<std::unique_ptr<XchangeService>> start(const std::filesystem::path& showFile,
                                                       const std::string& bindAddress, const XchangeOptions& options);
  // Sends MVR_LEAVE to the stations that joined, closes, joins the thread.
  ~XchangeService();
  XchangeService(const XchangeService&) = delete;
  XchangeService& operator=(const XchangeService&) = delete;

  // For the GUI's MVR-xchange window; safe from any thread (the station's thread answers).
  struct StationSeen {
    std::string name, uuid, provider;
    std::size_t files = 0;    // commits it announced
    std::string latestFile;   // the last one's uuid
    bool connected = false;   // a connection to it is open
    bool left = false;
  };
  std::vector<StationSeen> stations() const;
  int port() const;
  // Exports the show file as it is on disk and commits it to the stations now.
  void commitNow();
  // Asks a station for its latest file (imported into the accept folder when it comes).
  void request(const std::string& stationUuid);
  // The last lines the station logged (at most 50), oldest first.
  std::vector<std::string> recentLines() const;

  struct Impl;

 private:
  XchangeService() = default;
  std::unique_ptr<Impl> impl_;
};

}  // namespace haze
