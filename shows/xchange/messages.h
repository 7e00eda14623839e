// MVR-xchange messages (MVR 1.6, DIN SPEC 15801): the JSON documents stations send each other.
// One flat struct for every type: the fields a type does not use stay empty. Reading is lenient
// where stations differ in practice (numbers and booleans also as strings, a JOIN's file list
// under "Commits" or "Files", a LEAVE's uuid under "FromStationUUID" or "StationUUID") and
// strict where it matters: the payload is a JSON object, its "Type" is known, the fields the
// specification makes mandatory are there, and uuids are uuids.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fixtures/core/result.h"

namespace haze::xchange {

enum class MessageType {
  Join, JoinRet, Leave, LeaveRet, Commit, CommitRet, Request, RequestRet, NewSessionHost, NewSessionHostRet
};

// "MVR_JOIN" ... "MVR_NEW_SESSION_HOST_RET".
std::string messageTypeName(MessageType t);

// One revision of an MVR file a station offers (an MVR_COMMIT, and the entries of a JOIN's list).
struct CommitInfo {
  int verMajor = 1, verMinor = 6;  // the MVR version of the file
  std::uint64_t fileSize = 0;
  std::string fileUuid;            // lower case
  std::string stationUuid;         // the station that has it
  std::vector<std::string> forStations;  // empty: every station
  std::string comment;
  std::string fileName;            // a suggested name; never trusted as a path
};

struct Message {
  MessageType type = MessageType::Join;
  // JOIN and JOIN_RET: who is speaking and what it offers.
  std::string provider, stationName, stationUuid;
  int verMajor = 1, verMinor = 6;
  std::vector<CommitInfo> commits;
  // Every *_RET.
  bool ok = true;
  std::string message;
  // COMMIT.
  CommitInfo commit;
  // REQUEST (fileUuid empty: the latest file) and LEAVE.
  std::string fileUuid, fromStationUuid;
  // NEW_SESSION_HOST.
  std::string serviceName, serviceUrl;
};

// The JSON text of a message (compact, UTF-8).
std::string toJson(const Message& m);
// A payload as a message; an Error says what is wrong ("'FileUUID' is missing in MVR_COMMIT").
Result<Message> parseMessage(std::string_view json);

// "4aa291a1-1a62-45fe-aabc-e90e5e2399a8" (any case) as lower case; "" when not a uuid.
std::string normaliseUuid(std::string_view text);

// Shorthands for the replies.
Message reply(MessageType type, bool ok, std::string message = {});

}  // namespace haze::xchange
