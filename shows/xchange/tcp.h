// The TCP side of an MVR-xchange station: one listening socket and the connections to other
// stations (accepted, or dialled to an address from mDNS or --mvr-xchange-peer), each with its
// packet decoder and its queue of bytes to send. Plain POSIX sockets, non-blocking, one poll()
// per pump with a timeout; every queue, connection count and stall is bounded:
//   at most kMaxConnections connections (more are accepted and closed at once, logged);
//   a connection silent for stallSeconds in the middle of a packet is closed (truncated);
//   a dial that has not connected after connectSeconds is given up.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/xchange/station.h"

namespace haze::xchange {

struct Endpoint {
  std::string host;  // an IPv4 address ("127.0.0.1")
  int port = 0;
  std::string str() const { return host + ":" + std::to_string(port); }
};

// "127.0.0.1:5568" -> Endpoint; an Error that says what was expected.
Result<Endpoint> parseEndpoint(const std::string& text);

struct NodeHooks {
  // The bytes of a file haze offers (the station decides which); an Error is logged and the
  // request answered with REQUEST_RET OK false.
  std::function<Result<std::vector<std::uint8_t>>(const CommitInfo&)> fileBytes;
  // A received, checked MVR.
  std::function<void(ReceivedFile&&)> received;
  // One line per event.
  std::function<void(const std::string&)> log;
};

class Node {
 public:
  static constexpr int kMaxConnections = 32;
  double stallSeconds = 20.0;
  double connectSeconds = 5.0;

  // Listens on bindAddress:port (0 = a free port) for `station`, which must outlive the node.
  static Result<std::unique_ptr<Node>> listen(const std::string& bindAddress, int port, Station& station, NodeHooks hooks);
  ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  int port() const { return port_; }
  // Starts a connection to `to` and queues `first` (a JOIN) on it; the dial finishes in pump().
  Result<ConnectionId> dial(const Endpoint& to, const Message& first);
  // An open connection on which the station `uuid` spoke; 0 when there is none.
  ConnectionId connectionOf(const std::string& uuid) const;
  // Whether a connection to `to` that haze dialled is open (or still connecting).
  bool dialled(const Endpoint& to) const;
  void send(ConnectionId c, const Message& m);
  // A message to every connection whose station joined and did not leave; returns how many.
  int sendToJoined(const Message& m);
  // One poll() of every socket, waiting up to waitMs; reads, answers, writes what is ready.
  void pump(int waitMs);
  // Sends what is queued (up to waitMs in all) and closes every connection.
  void flushAndClose(int waitMs);
  std::size_t connections() const { return conns_.size(); }

 private:
  struct Conn;
  Node(Station& station, NodeHooks hooks);
  void accept();
  bool readFrom(ConnectionId id, Conn& c);
  bool writeTo(Conn& c);
  void react(ConnectionId id, Conn& c, Reaction r);
  void queue(Conn& c, const std::vector<std::uint8_t>& bytes);
  void log(const std::string& line) const;

  Station& station_;
  NodeHooks hooks_;
  int listenFd_ = -1;
  int port_ = 0;
  ConnectionId nextId_ = 1;
  std::map<ConnectionId, std::unique_ptr<Conn>> conns_;
};

}  // namespace haze::xchange
