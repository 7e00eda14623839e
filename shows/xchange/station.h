// An MVR-xchange station without sockets: what haze answers to each message, what it asks for,
// and what it keeps about the other stations. The transport (tcp.h) feeds it packets per
// connection and sends what it returns, so every exchange can be tested in memory.
//   JOIN        -> JOIN_RET with haze's name, uuid and the files it offers; the peer is listed
//   LEAVE       -> LEAVE_RET; the peer is no longer sent commits
//   COMMIT      -> COMMIT_RET; with requestCommits, a REQUEST for the file on the same connection
//   REQUEST     -> the file (a file packet), or REQUEST_RET OK false when haze does not have it
//   NEW_SESSION_HOST -> NEW_SESSION_HOST_RET OK false: haze stays in its group
//   a file      -> only after a REQUEST on that connection; checked (size, MVR archive)
// Anything else (a broken packet, JSON that is not a message, an unasked file) gets one line
// and the connection closed.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "shows/xchange/messages.h"
#include "shows/xchange/packet.h"

namespace haze::xchange {

struct Identity {
  std::string name;       // StationName
  std::string uuid;       // StationUUID, lower case
  std::string provider = "haze";
  int verMajor = 1, verMinor = 6;
};

struct PeerStation {
  std::string uuid, name, provider;
  std::vector<CommitInfo> commits;  // what it announced, in order
  bool left = false;                // sent MVR_LEAVE
};

using ConnectionId = int;

struct ReceivedFile {
  CommitInfo commit;                // as announced (fileUuid at least)
  std::vector<std::uint8_t> bytes;  // a checked MVR archive
};

// What the transport does after the station handled a packet, in this order: send `replies`,
// then the file `sendFile` names, then `request`; print `events`; hand `file` on; close.
struct Reaction {
  std::vector<Message> replies;
  std::optional<CommitInfo> sendFile;  // one of the offered files
  std::optional<Message> request;      // a REQUEST haze makes on this connection
  std::vector<std::string> events;     // one line each
  std::optional<ReceivedFile> file;
  bool close = false;
  std::string peer;  // the station that spoke, when the message names it
};

// The bytes of an MVR: a zip archive (within the zip limits) holding GeneralSceneDescription.xml.
// An Error names `source`.
Status checkMvrArchive(const std::vector<std::uint8_t>& bytes, const std::string& source);

class Station {
 public:
  // What is kept, so a station that floods haze with joins and commits costs bounded memory.
  static constexpr std::size_t kMaxOffered = 8;       // haze's own files, the latest
  static constexpr std::size_t kMaxPeers = 256;       // stations listed; later ones are not
  static constexpr std::size_t kMaxPeerCommits = 16;  // per station, the latest

  Station(Identity identity, Limits limits = {}) : id_(std::move(identity)), limits_(limits) {}

  const Identity& identity() const { return id_; }
  const Limits& limits() const { return limits_; }
  // With true, a COMMIT from another station is answered by a REQUEST for its file.
  void setRequestCommits(bool on) { requestCommits_ = on; }

  // A file haze offers from now on (the latest is the last, at most kMaxOffered: the oldest is
  // dropped); stationUuid is set to haze's.
  CommitInfo& offer(CommitInfo commit);
  const std::vector<CommitInfo>& offered() const { return offered_; }

  Message join() const;
  Message leave() const;
  Message commit(const CommitInfo& c) const;
  // A REQUEST for `fileUuid` ("" = the latest) on connection `c`; the file that answers it is
  // accepted on that connection only.
  Message request(ConnectionId c, const std::string& fileUuid, const std::string& fromStation);

  Reaction receive(ConnectionId c, const Packet& packet);
  // The stream on `c` broke or ended: its pending request is dropped, `why` logged when given.
  Reaction broken(ConnectionId c, const std::string& why);
  void closed(ConnectionId c) { pending_.erase(c); }

  const std::map<std::string, PeerStation>& peers() const { return peers_; }
  // Stations that joined and did not leave: the ones a commit goes to.
  std::vector<std::string> joinedPeers() const;

 private:
  Reaction onMessage(ConnectionId c, const Message& m);
  Reaction onFile(ConnectionId c, std::vector<std::uint8_t> bytes);
  Reaction onCommit(ConnectionId c, const Message& m);
  Reaction onRequest(const Message& m);
  void notePeer(const Message& m);
  PeerStation* peer(const std::string& uuid);  // listed, or listed now; nullptr when full
  std::string peerName(const std::string& uuid) const;

  Identity id_;
  Limits limits_;
  bool requestCommits_ = false;
  std::vector<CommitInfo> offered_;
  std::map<std::string, PeerStation> peers_;
  std::map<ConnectionId, CommitInfo> pending_;  // the file a connection owes haze
  std::set<std::string> received_;              // file uuids already fetched
};

}  // namespace haze::xchange
