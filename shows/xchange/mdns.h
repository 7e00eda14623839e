// MVR-xchange discovery over mDNS (RFC 6762/6763) through the Avahi daemon: haze registers the
// service `_mvrxchange._tcp` as "<StationName>@<group>" with the DNS-SD subtype
// `<group>._sub._mvrxchange._tcp` and the TXT records StationName and StationUUID, and browses
// `_mvrxchange._tcp` for the other stations of its group. No daemon (or no D-Bus) is not an
// error of haze: start() says why in one line and the station goes on with direct connections.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/xchange/station.h"
#include "shows/xchange/tcp.h"

namespace haze::xchange {

struct Discovered {
  Endpoint endpoint;
  std::string name, uuid;  // TXT StationName and StationUUID
  std::string instance;    // the service instance name
};

class Mdns {
 public:
  // Registers and browses; an Error ("avahi-daemon is not reachable: Daemon not running") when
  // mDNS cannot be used.
  static Result<std::unique_ptr<Mdns>> start(const Identity& me, const std::string& group, int port);
  ~Mdns();
  Mdns(const Mdns&) = delete;
  Mdns& operator=(const Mdns&) = delete;

  // Runs Avahi's pending work without waiting; then the stations found since the last call.
  std::vector<Discovered> pump();
  // Lines for the log (registered, a name collision, the daemon gone).
  std::vector<std::string> takeNotes();

  struct State;

 private:
  Mdns() = default;
  std::unique_ptr<State> s_;
};

// "<name>@<group>": whether a service instance belongs to `group` (names without '@' are taken
// as any group's, as some stations announce only their name).
bool instanceInGroup(const std::string& instance, const std::string& group);

}  // namespace haze::xchange
