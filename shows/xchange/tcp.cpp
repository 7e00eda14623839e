#include "shows/xchange/tcp.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace haze::xchange {
namespace {

double nowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool nonBlocking(int fd) {
  const int flags = fcntl(fd, F_GETFL, 0);
  return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

std::string addressOf(const sockaddr_in& a) {
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
  return std::string(text) + ":" + std::to_string(ntohs(a.sin_port));
}

}  // namespace

struct Node::Conn {
  int fd = -1;
  std::string where;          // "127.0.0.1:40000", for the log
  bool dialled = false;
  Endpoint endpoint;          // when dialled
  bool connecting = false;
  double since = 0.0;         // when the dial started, or the last byte came
  PacketDecoder decoder;
  std::vector<std::uint8_t> out;
  std::size_t sent = 0;
  std::string peer;           // the station's uuid, once it named itself
  // Inside a packet and nothing came for `limit` seconds: a peer that stopped mid-transfer.
  bool payloadStalled(double now, double limit) const {
    return (decoder.payloadExpected() > 0 || !decoder.finish()) && now - since > limit;
  }
  ~Conn() {
    if (fd >= 0) ::close(fd);
  }
};

Result<Endpoint> parseEndpoint(const std::string& text) {
  const auto colon = text.rfind(':');
  Endpoint e;
  in_addr probe{};
  if (colon == std::string::npos || inet_pton(AF_INET, text.substr(0, colon).c_str(), &probe) != 1)
    return Error{"", "", "'" + text + "' is not HOST:PORT with an IPv4 address (e.g. 127.0.0.1:4568)"};
  e.host = text.substr(0, colon);
  const std::string port = text.substr(colon + 1);
  if (port.empty() || port.size() > 5 || port.find_first_not_of("0123456789") != std::string::npos ||
      std::stoi(port) < 1 || std::stoi(port) > 65535)
    return Error{"", "", "'" + text + "' has no port 1..65535"};
  e.port = std::stoi(port);
  return e;
}

Result<std::unique_ptr<Node>> Node::listen(const std::string& bindAddress, int port, Station& station, NodeHooks hooks) {
  std::unique_ptr<Node> node(new Node(station, std::move(hooks)));
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  if (inet_pton(AF_INET, bindAddress.c_str(), &a.sin_addr) != 1)
    return Error{"", "", "--bind '" + bindAddress + "' is not an IPv4 address"};
  node->listenFd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (node->listenFd_ < 0) return Error{"", "", std::string("MVR-xchange: socket: ") + std::strerror(errno)};
  const int one = 1;
  setsockopt(node->listenFd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(node->listenFd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(node->listenFd_, 16) != 0 ||
      !nonBlocking(node->listenFd_))
    return Error{"", "", "MVR-xchange: cannot listen on " + bindAddress + ":" + std::to_string(port) + ": " +
                             std::strerror(errno)};
  socklen_t len = sizeof a;
  getsockname(node->listenFd_, reinterpret_cast<sockaddr*>(&a), &len);
  node->port_ = ntohs(a.sin_port);
  return node;
}

Node::Node(Station& station, NodeHooks hooks) : station_(station), hooks_(std::move(hooks)) {}

Node::~Node() {
  conns_.clear();
  if (listenFd_ >= 0) ::close(listenFd_);
}

void Node::log(const std::string& line) const {
  if (hooks_.log) hooks_.log(line);
}

void Node::queue(Conn& c, const std::vector<std::uint8_t>& bytes) { c.out.insert(c.out.end(), bytes.begin(), bytes.end()); }

void Node::send(ConnectionId id, const Message& m) {
  auto it = conns_.find(id);
  if (it != conns_.end()) queue(*it->second, encodeJsonPacket(toJson(m)));
}

int Node::sendToJoined(const Message& m) {
  int n = 0;
  for (auto& [id, c] : conns_) {
    auto p = station_.peers().find(c->peer);
    if (p == station_.peers().end() || p->second.left) continue;
    queue(*c, encodeJsonPacket(toJson(m)));
    ++n;
  }
  return n;
}

ConnectionId Node::connectionOf(const std::string& uuid) const {
  for (const auto& [id, c] : conns_)
    if (!uuid.empty() && c->peer == uuid && c->fd >= 0 && !c->connecting) return id;
  return 0;
}

bool Node::dialled(const Endpoint& to) const {
  for (const auto& [id, c] : conns_)
    if (c->dialled && c->endpoint.host == to.host && c->endpoint.port == to.port) return true;
  return false;
}

Result<ConnectionId> Node::dial(const Endpoint& to, const Message& first) {
  if (conns_.size() >= kMaxConnections) return Error{"", "", "MVR-xchange: " + std::to_string(kMaxConnections) + " connections are open"};
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(to.port));
  if (inet_pton(AF_INET, to.host.c_str(), &a.sin_addr) != 1) return Error{"", "", to.str() + " is not an IPv4 address"};
  auto c = std::make_unique<Conn>();
  c->fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (c->fd < 0 || !nonBlocking(c->fd)) return Error{"", "", std::string("MVR-xchange: socket: ") + std::strerror(errno)};
  if (::connect(c->fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 && errno != EINPROGRESS)
    return Error{"", "", "MVR-xchange: cannot connect to " + to.str() + ": " + std::strerror(errno)};
  c->where = to.str();
  c->decoder = PacketDecoder(station_.limits());
  c->dialled = true;
  c->endpoint = to;
  c->connecting = true;
  c->since = nowS();
  queue(*c, encodeJsonPacket(toJson(first)));
  const ConnectionId id = nextId_++;
  conns_[id] = std::move(c);
  return id;
}

void Node::accept() {
  for (int k = 0; k < 16; ++k) {
    sockaddr_in from{};
    socklen_t len = sizeof from;
    const int fd = ::accept4(listenFd_, reinterpret_cast<sockaddr*>(&from), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;
    if (conns_.size() >= kMaxConnections) {
      log("connection from " + addressOf(from) + " refused: " + std::to_string(kMaxConnections) + " are open");
      ::close(fd);
      continue;
    }
    auto c = std::make_unique<Conn>();
    c->fd = fd;
    c->where = addressOf(from);
    c->since = nowS();
    c->decoder = PacketDecoder(station_.limits());
    conns_[nextId_++] = std::move(c);
  }
}

void Node::react(ConnectionId id, Conn& c, Reaction r) {
  if (!r.peer.empty()) c.peer = r.peer;
  for (const std::string& e : r.events) log(c.where + ": " + e);
  for (const Message& m : r.replies) queue(c, encodeJsonPacket(toJson(m)));
  if (r.sendFile && c.out.size() - c.sent > station_.limits().maxFileBytes) {
    // A peer that asks again and again without reading: its queue stays bounded.
    log(c.where + ": MVR_REQUEST refused: the station does not read what it asked for; connection closed");
    r.sendFile.reset();
    r.close = true;
  }
  if (r.sendFile) {
    Result<std::vector<std::uint8_t>> bytes =
        hooks_.fileBytes ? hooks_.fileBytes(*r.sendFile) : Result<std::vector<std::uint8_t>>(Error{"", "", "no files"});
    if (bytes) {
      const auto header = encodeHeader(PayloadType::File, bytes->size());
      c.out.insert(c.out.end(), header.begin(), header.end());
      queue(c, *bytes);
    } else {
      log(c.where + ": " + bytes.error().str());
      queue(c, encodeJsonPacket(toJson(reply(MessageType::RequestRet, false, "The MVR could not be read on this station"))));
    }
  }
  if (r.request) queue(c, encodeJsonPacket(toJson(*r.request)));
  if (r.file && hooks_.received) hooks_.received(std::move(*r.file));
  if (r.close) {
    station_.closed(id);
    ::close(c.fd);
    c.fd = -1;
  }
}

// Reads what is there (bounded per pump, so one fast peer cannot starve the rest); false when
// the connection is done with (closed by the peer, broken, or refused).
bool Node::readFrom(ConnectionId id, Conn& c) {
  std::uint8_t buf[65536];
  for (int k = 0; k < 64 && c.fd >= 0; ++k) {
    const ssize_t n = ::recv(c.fd, buf, sizeof buf, 0);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return true;
    if (n <= 0) {
      Status end = c.decoder.finish();
      const std::string why = n < 0 ? std::string(std::strerror(errno)) : end ? "" : end.error().str();
      if (!why.empty()) react(id, c, station_.broken(id, why));
      else log(c.where + ": connection closed");
      station_.closed(id);
      return false;
    }
    c.since = nowS();
    if (Status s = c.decoder.feed(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n))); !s) {
      react(id, c, station_.broken(id, s.error().str()));
      return false;
    }
    Packet p;
    while (c.fd >= 0 && c.decoder.next(p)) react(id, c, station_.receive(id, p));
  }
  return c.fd >= 0;
}

bool Node::writeTo(Conn& c) {
  while (c.sent < c.out.size()) {
    const ssize_t n = ::send(c.fd, c.out.data() + c.sent, c.out.size() - c.sent, MSG_NOSIGNAL);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return true;
    if (n <= 0) {
      log(c.where + ": send failed: " + std::strerror(errno));
      return false;
    }
    c.sent += static_cast<std::size_t>(n);
  }
  c.out.clear();
  c.sent = 0;
  return true;
}

void Node::pump(int waitMs) {
  std::vector<pollfd> fds;
  std::vector<ConnectionId> ids;
  fds.push_back({listenFd_, POLLIN, 0});
  for (const auto& [id, c] : conns_) {
    short events = c->connecting ? POLLOUT : POLLIN;
    if (!c->out.empty()) events |= POLLOUT;
    fds.push_back({c->fd, events, 0});
    ids.push_back(id);
  }
  if (::poll(fds.data(), fds.size(), std::max(0, waitMs)) < 0) return;
  if (fds[0].revents & POLLIN) accept();
  const double now = nowS();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    auto it = conns_.find(ids[k]);
    Conn& c = *it->second;
    bool keep = true;
    const short ev = fds[k + 1].revents;
    if (c.connecting) {
      if (ev & (POLLOUT | POLLERR | POLLHUP)) {
        int err = 0;
        socklen_t len = sizeof err;
        getsockopt(c.fd, SOL_SOCKET, SO_ERROR, &err, &len);
        if (err != 0) {
          log("cannot connect to " + c.where + ": " + std::strerror(err));
          keep = false;
        } else {
          c.connecting = false;
          c.since = now;
          log("connected to " + c.where);
        }
      } else if (now - c.since > connectSeconds) {
        log("cannot connect to " + c.where + ": no answer in " + std::to_string(static_cast<int>(connectSeconds)) + " s");
        keep = false;
      }
    } else {
      if (ev & (POLLIN | POLLHUP | POLLERR)) keep = readFrom(ids[k], c);
      if (keep && c.payloadStalled(now, stallSeconds)) {
        react(ids[k], c, station_.broken(ids[k], "truncated packet: no byte for " +
                                                     std::to_string(static_cast<int>(stallSeconds)) + " s"));
        keep = false;
      }
    }
    if (keep && c.fd >= 0 && !c.connecting && !c.out.empty()) keep = writeTo(c);
    if (!keep || c.fd < 0) {
      station_.closed(ids[k]);
      conns_.erase(it);
    }
  }
}

void Node::flushAndClose(int waitMs) {
  const double until = nowS() + waitMs / 1000.0;
  for (;;) {
    bool pending = false;
    for (const auto& [id, c] : conns_) pending = pending || (!c->connecting && !c->out.empty());
    if (!pending || nowS() >= until) break;
    pump(20);
  }
  conns_.clear();
}

}  // namespace haze::xchange
