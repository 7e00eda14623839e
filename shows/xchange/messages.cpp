#include "shows/xchange/messages.h"

#include <array>
#include <cctype>
#include <utility>

#include <nlohmann/json.hpp>

namespace haze::xchange {
namespace {

using nlohmann::json;

constexpr std::array<std::pair<MessageType, const char*>, 10> kNames = {{
    {MessageType::Join, "MVR_JOIN"},
    {MessageType::JoinRet, "MVR_JOIN_RET"},
    {MessageType::Leave, "MVR_LEAVE"},
    {MessageType::LeaveRet, "MVR_LEAVE_RET"},
    {MessageType::Commit, "MVR_COMMIT"},
    {MessageType::CommitRet, "MVR_COMMIT_RET"},
    {MessageType::Request, "MVR_REQUEST"},
    {MessageType::RequestRet, "MVR_REQUEST_RET"},
    {MessageType::NewSessionHost, "MVR_NEW_SESSION_HOST"},
    {MessageType::NewSessionHostRet, "MVR_NEW_SESSION_HOST_RET"},
}};

bool isReply(MessageType t) {
  return t == MessageType::JoinRet || t == MessageType::LeaveRet || t == MessageType::CommitRet ||
         t == MessageType::RequestRet || t == MessageType::NewSessionHostRet;
}

// Reads one object's fields with the message's name in every error.
class Fields {
 public:
  Fields(const json& j, std::string what) : j_(j), what_(std::move(what)) {}

  const json* find(const char* key) const {
    auto it = j_.find(key);
    return it == j_.end() || it->is_null() ? nullptr : &*it;
  }
  Error missing(const char* key) const { return Error{"", "", "'" + std::string(key) + "' is missing in " + what_}; }
  Error wrong(const char* key, const char* expected) const {
    return Error{"", "", "'" + std::string(key) + "' in " + what_ + " is not " + expected};
  }

  Result<std::string> text(const char* key, bool required) const {
    const json* v = find(key);
    if (!v) return required ? Result<std::string>(missing(key)) : Result<std::string>(std::string());
    if (!v->is_string()) return wrong(key, "a string");
    return v->get<std::string>();
  }
  Result<std::string> uuid(const char* key, bool required) const {
    Result<std::string> t = text(key, required);
    if (!t || t->empty()) return t;
    std::string u = normaliseUuid(*t);
    if (u.empty()) return wrong(key, "a uuid (8-4-4-4-12 hexadecimal digits)");
    return u;
  }
  // A whole number 0..max, also written as a string ("6"): stations send both.
  Result<std::uint64_t> number(const char* key, bool required, std::uint64_t fallback, std::uint64_t max) const {
    const json* v = find(key);
    if (!v) return required ? Result<std::uint64_t>(missing(key)) : Result<std::uint64_t>(fallback);
    std::uint64_t n = 0;
    if (v->is_number_unsigned()) {
      n = v->get<std::uint64_t>();
    } else if (v->is_number_integer() && v->get<std::int64_t>() >= 0) {
      n = static_cast<std::uint64_t>(v->get<std::int64_t>());
    } else if (v->is_string()) {
      const std::string& s = v->get_ref<const std::string&>();
      if (s.empty() || s.size() > 19) return wrong(key, "a whole number");
      for (char c : s) {
        if (!std::isdigit(static_cast<unsigned char>(c))) return wrong(key, "a whole number");
        n = n * 10 + static_cast<std::uint64_t>(c - '0');
      }
    } else {
      return wrong(key, "a whole number");
    }
    if (n > max) return wrong(key, ("a whole number up to " + std::to_string(max)).c_str());
    return n;
  }
  Result<bool> flag(const char* key) const {
    const json* v = find(key);
    if (!v) return missing(key);
    if (v->is_boolean()) return v->get<bool>();
    if (v->is_string() && (*v == "true" || *v == "false")) return *v == "true";
    return wrong(key, "true or false");
  }

 private:
  const json& j_;
  std::string what_;
};

// Assigns a Result's value to `target`, or returns its Error from the enclosing function.
#define HAZE_TRY(target, expr)                 \
  do {                                         \
    auto tried_ = (expr);                      \
    if (!tried_) return tried_.error();        \
    target = std::move(*tried_);               \
  } while (0)

Result<CommitInfo> readCommit(const json& j, const std::string& what, bool inList) {
  if (!j.is_object()) return Error{"", "", what + " is not a JSON object"};
  const Fields f(j, what);
  CommitInfo c;
  std::uint64_t major = 0, minor = 0;
  HAZE_TRY(major, f.number("verMajor", false, 0, 1000));
  HAZE_TRY(minor, f.number("verMinor", false, 0, 1000));
  c.verMajor = static_cast<int>(major);
  c.verMinor = static_cast<int>(minor);
  HAZE_TRY(c.fileSize, f.number("FileSize", !inList, 0, UINT64_MAX));
  HAZE_TRY(c.fileUuid, f.uuid("FileUUID", true));
  HAZE_TRY(c.stationUuid, f.uuid("StationUUID", false));
  HAZE_TRY(c.comment, f.text("Comment", false));
  HAZE_TRY(c.fileName, f.text("FileName", false));
  if (const json* list = f.find("ForStationsUUID")) {
    if (!list->is_array()) return f.wrong("ForStationsUUID", "an array of uuids");
    for (const json& u : *list) {
      const std::string n = u.is_string() ? normaliseUuid(u.get<std::string>()) : "";
      if (n.empty()) return f.wrong("ForStationsUUID", "an array of uuids");
      c.forStations.push_back(n);
    }
  }
  return c;
}

json commitJson(const CommitInfo& c, bool withType) {
  json j = json::object();
  if (withType) j["Type"] = "MVR_COMMIT";
  j["verMajor"] = c.verMajor;
  j["verMinor"] = c.verMinor;
  j["FileSize"] = c.fileSize;
  j["FileUUID"] = c.fileUuid;
  j["StationUUID"] = c.stationUuid;
  j["ForStationsUUID"] = c.forStations;
  j["Comment"] = c.comment;
  if (!c.fileName.empty()) j["FileName"] = c.fileName;
  return j;
}

Status readStation(const Fields& f, Message& m, bool required) {
  HAZE_TRY(m.provider, f.text("Provider", required));
  HAZE_TRY(m.stationName, f.text("StationName", required));
  HAZE_TRY(m.stationUuid, f.uuid("StationUUID", required));
  std::uint64_t major = 0, minor = 0;
  HAZE_TRY(major, f.number("verMajor", false, 0, 1000));
  HAZE_TRY(minor, f.number("verMinor", false, 0, 1000));
  m.verMajor = static_cast<int>(major);
  m.verMinor = static_cast<int>(minor);
  const char* key = f.find("Commits") ? "Commits" : "Files";
  if (const json* list = f.find(key)) {
    if (!list->is_array()) return f.wrong(key, "an array of commits");
    if (list->size() > 10000) return f.wrong(key, "a list of up to 10000 commits");
    for (std::size_t i = 0; i < list->size(); ++i) {
      Result<CommitInfo> c = readCommit((*list)[i], std::string(key) + "[" + std::to_string(i) + "] of " +
                                                        messageTypeName(m.type), true);
      if (!c) return c.error();
      m.commits.push_back(std::move(*c));
    }
  }
  return Ok{};
}

Status readBody(const Fields& f, Message& m) {
  if (isReply(m.type)) {
    HAZE_TRY(m.ok, f.flag("OK"));
    HAZE_TRY(m.message, f.text("Message", false));
  }
  switch (m.type) {
    case MessageType::Join: return readStation(f, m, true);
    case MessageType::JoinRet: return readStation(f, m, false);
    case MessageType::Leave: {
      const char* key = f.find("FromStationUUID") ? "FromStationUUID" : "StationUUID";
      HAZE_TRY(m.fromStationUuid, f.uuid(key, false));
      if (m.fromStationUuid.empty()) return f.missing("FromStationUUID");
      return Ok{};
    }
    case MessageType::Request: {
      HAZE_TRY(m.fileUuid, f.uuid("FileUUID", false));
      // A string in the examples, an array in the table: both are read.
      if (const json* from = f.find("FromStationUUID"); from && from->is_array()) {
        if (!from->empty()) {
          if (!(*from)[0].is_string() || normaliseUuid((*from)[0].get<std::string>()).empty())
            return f.wrong("FromStationUUID", "a uuid");
          m.fromStationUuid = normaliseUuid((*from)[0].get<std::string>());
        }
      } else {
        HAZE_TRY(m.fromStationUuid, f.uuid("FromStationUUID", false));
      }
      return Ok{};
    }
    case MessageType::NewSessionHost:
      HAZE_TRY(m.serviceName, f.text("ServiceName", false));
      HAZE_TRY(m.serviceUrl, f.text("ServiceURL", false));
      return Ok{};
    default: return Ok{};
  }
}

}  // namespace

std::string messageTypeName(MessageType t) {
  for (const auto& [type, name] : kNames)
    if (type == t) return name;
  return "?";
}

std::string normaliseUuid(std::string_view text) {
  if (text.size() != 36) return {};
  std::string out(text);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
    const auto c = static_cast<unsigned char>(out[i]);
    if (dash ? c != '-' : !std::isxdigit(c)) return {};
    out[i] = static_cast<char>(std::tolower(c));
  }
  return out;
}

Message reply(MessageType type, bool ok, std::string message) {
  Message m;
  m.type = type;
  m.ok = ok;
  m.message = std::move(message);
  return m;
}

std::string toJson(const Message& m) {
  json j = m.type == MessageType::Commit ? commitJson(m.commit, true) : json::object();
  j["Type"] = messageTypeName(m.type);
  if (isReply(m.type)) {
    j["OK"] = m.ok;
    j["Message"] = m.message;
  }
  if (m.type == MessageType::Join || m.type == MessageType::JoinRet) {
    j["Provider"] = m.provider;
    j["StationName"] = m.stationName;
    j["StationUUID"] = m.stationUuid;
    j["verMajor"] = m.verMajor;
    j["verMinor"] = m.verMinor;
    json list = json::array();
    for (const CommitInfo& c : m.commits) list.push_back(commitJson(c, false));
    j["Commits"] = list;
  } else if (m.type == MessageType::Leave) {
    j["FromStationUUID"] = m.fromStationUuid;
  } else if (m.type == MessageType::Request) {
    j["FileUUID"] = m.fileUuid;
    j["FromStationUUID"] = m.fromStationUuid;
  } else if (m.type == MessageType::NewSessionHost) {
    j["ServiceName"] = m.serviceName;
    j["ServiceURL"] = m.serviceUrl;
  }
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

Result<Message> parseMessage(std::string_view text) {
  json j = json::parse(text.begin(), text.end(), nullptr, false);
  if (j.is_discarded()) return Error{"", "", "the JSON message does not parse"};
  if (!j.is_object()) return Error{"", "", "the JSON message is not an object"};
  auto type = j.find("Type");
  if (type == j.end()) return Error{"", "", "the JSON message has no 'Type'"};
  if (!type->is_string()) return Error{"", "", "the message's 'Type' is not a string"};
  Message m;
  bool known = false;
  for (const auto& [t, name] : kNames)
    if (*type == name) {
      m.type = t;
      known = true;
    }
  if (!known) {
    std::string name = type->get<std::string>().substr(0, 40);
    for (char& c : name)
      if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    return Error{"", "", "unknown message type '" + name + "'"};
  }
  const Fields f(j, messageTypeName(m.type));
  if (m.type == MessageType::Commit) {
    Result<CommitInfo> c = readCommit(j, "MVR_COMMIT", false);
    if (!c) return c.error();
    m.commit = std::move(*c);
    return m;
  }
  if (Status s = readBody(f, m); !s) return s.error();
  return m;
}

}  // namespace haze::xchange
