#include "shows/xchange/station.h"

#include <algorithm>

#include "fixtures/core/zip_archive.h"

namespace haze::xchange {

Status checkMvrArchive(const std::vector<std::uint8_t>& bytes, const std::string& source) {
  Result<ZipArchive> zip = ZipArchive::fromMemory(bytes, source);
  if (!zip) return zip.error();
  if (!zip->contains("GeneralSceneDescription.xml"))
    return Error{source, "", "the archive has no GeneralSceneDescription.xml; expected an MVR file"};
  return Ok{};
}

CommitInfo& Station::offer(CommitInfo commit) {
  commit.stationUuid = id_.uuid;
  offered_.push_back(std::move(commit));
  if (offered_.size() > kMaxOffered) offered_.erase(offered_.begin());
  return offered_.back();
}

Message Station::join() const {
  Message m;
  m.type = MessageType::Join;
  m.provider = id_.provider;
  m.stationName = id_.name;
  m.stationUuid = id_.uuid;
  m.verMajor = id_.verMajor;
  m.verMinor = id_.verMinor;
  m.commits = offered_;
  return m;
}

Message Station::leave() const {
  Message m;
  m.type = MessageType::Leave;
  m.fromStationUuid = id_.uuid;
  return m;
}

Message Station::commit(const CommitInfo& c) const {
  Message m;
  m.type = MessageType::Commit;
  m.commit = c;
  m.commit.stationUuid = id_.uuid;
  return m;
}

Message Station::request(ConnectionId c, const std::string& fileUuid, const std::string& fromStation) {
  Message m;
  m.type = MessageType::Request;
  m.fileUuid = fileUuid;
  m.fromStationUuid = fromStation;
  CommitInfo owed;
  owed.fileUuid = fileUuid;
  owed.stationUuid = fromStation;
  // What the file will be: the commit it named, or for the latest the station's last one.
  if (auto p = peers_.find(fromStation); p != peers_.end()) {
    if (fileUuid.empty() && !p->second.commits.empty()) owed = p->second.commits.back();
    for (const CommitInfo& k : p->second.commits)
      if (!fileUuid.empty() && k.fileUuid == fileUuid) owed = k;
  }
  pending_[c] = owed;
  return m;
}

std::vector<std::string> Station::joinedPeers() const {
  std::vector<std::string> out;
  for (const auto& [uuid, p] : peers_)
    if (!p.left) out.push_back(uuid);
  return out;
}

std::string Station::peerName(const std::string& uuid) const {
  auto p = peers_.find(uuid);
  if (p == peers_.end() || p->second.name.empty()) return uuid.empty() ? "a station" : "station " + uuid;
  return "\"" + p->second.name + "\" (" + uuid + ")";
}

PeerStation* Station::peer(const std::string& uuid) {
  if (uuid.empty() || uuid == id_.uuid) return nullptr;
  auto it = peers_.find(uuid);
  if (it == peers_.end()) {
    if (peers_.size() >= kMaxPeers) return nullptr;
    it = peers_.emplace(uuid, PeerStation{}).first;
    it->second.uuid = uuid;
  }
  return &it->second;
}

void Station::notePeer(const Message& m) {
  PeerStation* p = peer(m.stationUuid);
  if (!p) return;
  p->name = m.stationName.substr(0, 200);
  p->provider = m.provider.substr(0, 200);
  p->commits = m.commits;
  if (p->commits.size() > kMaxPeerCommits)
    p->commits.erase(p->commits.begin(), p->commits.end() - static_cast<long>(kMaxPeerCommits));
  p->left = false;
}

Reaction Station::broken(ConnectionId c, const std::string& why) {
  Reaction r;
  pending_.erase(c);
  if (!why.empty()) r.events.push_back(why + "; connection closed, nothing written");
  r.close = true;
  return r;
}

Reaction Station::receive(ConnectionId c, const Packet& packet) {
  if (packet.type == PayloadType::File) return onFile(c, packet.payload);
  const std::string text(packet.payload.begin(), packet.payload.end());
  Result<Message> m = parseMessage(text);
  if (!m) return broken(c, m.error().str());
  return onMessage(c, *m);
}

Reaction Station::onMessage(ConnectionId c, const Message& m) {
  Reaction r;
  r.peer = m.type == MessageType::Leave ? m.fromStationUuid : m.stationUuid;
  switch (m.type) {
    case MessageType::Join:
      notePeer(m);
      r.events.push_back("MVR_JOIN from " + peerName(m.stationUuid) + ", " + std::to_string(m.commits.size()) + " file" +
                         (m.commits.size() == 1 ? "" : "s"));
      r.replies.push_back(join());
      r.replies.back().type = MessageType::JoinRet;
      r.replies.back().ok = true;
      return r;
    case MessageType::JoinRet:
      if (!m.ok) {
        r.events.push_back("MVR_JOIN refused by " + peerName(m.stationUuid) + ": " + m.message.substr(0, 200));
        return r;
      }
      notePeer(m);
      r.events.push_back("joined " + peerName(m.stationUuid) + ", " + std::to_string(m.commits.size()) + " file" +
                         (m.commits.size() == 1 ? "" : "s"));
      return r;
    case MessageType::Leave:
      if (auto p = peers_.find(m.fromStationUuid); p != peers_.end()) p->second.left = true;
      r.events.push_back("MVR_LEAVE from " + peerName(m.fromStationUuid));
      r.replies.push_back(reply(MessageType::LeaveRet, true));
      return r;
    case MessageType::Commit: {
      r = onCommit(c, m);
      r.peer = m.commit.stationUuid;
      return r;
    }
    case MessageType::Request: return onRequest(m);
    case MessageType::RequestRet:
      if (pending_.erase(c)) r.events.push_back("MVR_REQUEST refused: " + m.message.substr(0, 200));
      return r;
    case MessageType::NewSessionHost:
      r.events.push_back("MVR_NEW_SESSION_HOST refused: haze stays in its group");
      r.replies.push_back(reply(MessageType::NewSessionHostRet, false, "haze does not move to another session host"));
      return r;
    case MessageType::CommitRet:
    case MessageType::LeaveRet:
    case MessageType::NewSessionHostRet:
      if (!m.ok) r.events.push_back(messageTypeName(m.type) + " not OK: " + m.message.substr(0, 200));
      return r;
  }
  return r;
}

Reaction Station::onCommit(ConnectionId c, const Message& m) {
  Reaction r;
  const CommitInfo& k = m.commit;
  const std::string from = k.stationUuid;
  if (PeerStation* p = peer(from)) {
    p->left = false;
    p->commits.push_back(k);
    if (p->commits.size() > kMaxPeerCommits) p->commits.erase(p->commits.begin());
  }
  r.events.push_back("MVR_COMMIT from " + peerName(from) + ": file " + k.fileUuid + ", " + std::to_string(k.fileSize) +
                     " bytes" + (k.comment.empty() ? "" : ", \"" + k.comment.substr(0, 200) + "\""));
  r.replies.push_back(reply(MessageType::CommitRet, true));
  const bool forUs = k.forStations.empty() ||
                     std::find(k.forStations.begin(), k.forStations.end(), id_.uuid) != k.forStations.end();
  if (!requestCommits_ || !forUs || received_.count(k.fileUuid)) return r;
  if (k.fileSize > limits_.maxFileBytes) {
    r.events.push_back("file " + k.fileUuid + " not requested: " + std::to_string(k.fileSize) +
                       " bytes is over the limit of " + std::to_string(limits_.maxFileBytes >> 20) + " MiB");
    return r;
  }
  r.request = request(c, k.fileUuid, from);
  pending_[c] = k;
  return r;
}

Reaction Station::onRequest(const Message& m) {
  Reaction r;
  const CommitInfo* found = nullptr;
  if (m.fileUuid.empty() && !offered_.empty()) found = &offered_.back();
  for (const CommitInfo& k : offered_)
    if (k.fileUuid == m.fileUuid) found = &k;
  if (!found) {
    r.events.push_back("MVR_REQUEST for " + (m.fileUuid.empty() ? std::string("the latest file") : "file " + m.fileUuid) +
                       ": haze does not have it");
    r.replies.push_back(reply(MessageType::RequestRet, false, "The MVR is not available on this station"));
    return r;
  }
  r.events.push_back("MVR_REQUEST for file " + found->fileUuid + ": sending " + std::to_string(found->fileSize) + " bytes");
  r.sendFile = *found;
  return r;
}

Reaction Station::onFile(ConnectionId c, std::vector<std::uint8_t> bytes) {
  auto owed = pending_.find(c);
  if (owed == pending_.end()) return broken(c, "an MVR file came that haze did not request");
  CommitInfo k = owed->second;
  pending_.erase(owed);
  const std::string source = "MVR file " + (k.fileUuid.empty() ? std::string("(latest)") : k.fileUuid);
  if (k.fileSize != 0 && bytes.size() != k.fileSize)
    return broken(c, source + ": " + std::to_string(bytes.size()) + " bytes came, the commit announced " +
                         std::to_string(k.fileSize));
  if (Status s = checkMvrArchive(bytes, source); !s) return broken(c, s.error().str());
  Reaction r;
  if (!k.fileUuid.empty()) received_.insert(k.fileUuid);
  k.fileSize = bytes.size();
  r.events.push_back(source + " received, " + std::to_string(bytes.size()) + " bytes");
  r.file = ReceivedFile{std::move(k), std::move(bytes)};
  return r;
}

}  // namespace haze::xchange
