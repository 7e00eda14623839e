// POSIX UDP receive for Art-Net and sACN: non-blocking sockets, poll() with a timeout, a bounded
// number of datagrams per pump so a flood cannot stall the frame loop.
#include "shows/dmx/udp_receiver.h"

#include "shows/dmx/artnet_poll.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace haze {

namespace {

std::string ipString(uint32_t hostOrder) {
  in_addr a{};
  a.s_addr = htonl(hostOrder);
  char s[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &a, s, sizeof s);
  return s;
}

// A non-blocking UDP socket bound to address:port; port 0 picks a free one. The port is shared
// (SO_REUSEADDR and SO_REUSEPORT): a technician's laptop often runs olad or another visualiser
// on 6454 and 5568 too. Broadcast and multicast datagrams then reach every program; a unicast
// one reaches only one of them, the kernel's choice (docs/live.md).
Result<int> bindUdp(uint32_t addressHostOrder, int port, const char* what) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) return Error{"", "", std::string("cannot create the ") + what + " socket: " + std::strerror(errno)};
  const int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  setsockopt(fd, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
  const int rcvbuf = 1 << 20;  // bursts from a console's many universes
  setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<uint16_t>(port));
  sa.sin_addr.s_addr = htonl(addressHostOrder);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    return Error{"", "", std::string("cannot listen for ") + what + " on " + ipString(addressHostOrder) + ":" +
                             std::to_string(port) + ": " + reason +
                             "; expected an address of this machine and a free port (is another receiver running?)"};
  }
  return fd;
}

// Whether another socket already holds address:port in a way that shares its unicast datagrams
// with ours: a probe bound without SO_REUSEADDR and SO_REUSEPORT fails with EADDRINUSE exactly
// when a socket on the same port has the same address, or either side is 0.0.0.0 (a socket on
// another address of the same port, 127.0.0.2 beside 127.0.0.1, shares nothing and is no
// conflict). The kernel's own rule, so it holds in network namespaces, for other users'
// sockets and where /proc is not mounted. Any other failure says nothing about sharing.
bool portTaken(uint32_t addressHostOrder, int port) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<uint16_t>(port));
  sa.sin_addr.s_addr = htonl(addressHostOrder);
  const bool taken = ::bind(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0 && errno == EADDRINUSE;
  ::close(fd);
  return taken;
}

std::string sharedPortWarning(uint32_t addressHostOrder, int port, const char* what) {
  return std::string("warning: another program already listens on ") + ipString(addressHostOrder) + ":" +
         std::to_string(port) + ": " + what + " sent unicast to this address reaches only one of the two (the " +
         "kernel picks which); give haze an address of its own with --bind, or send sACN multicast (docs/live.md, " +
         "\"Sharing the ports\")";
}

int boundPort(int fd) {
  sockaddr_in sa{};
  socklen_t len = sizeof sa;
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&sa), &len) != 0) return 0;
  return ntohs(sa.sin_port);
}

}  // namespace

Result<std::unique_ptr<UdpReceiver>> UdpReceiver::open(const UdpReceiverOptions& o) {
  in_addr bindAddr{};
  if (inet_pton(AF_INET, o.bindAddress.c_str(), &bindAddr) != 1) {
    return Error{"", "--bind", "'" + o.bindAddress + "' is not an IPv4 address; expected one like 127.0.0.1 or 192.168.1.20"};
  }
  for (int port : {o.artNetPort, o.sacnPort}) {
    if (port < 0 || port > 65535) {
      return Error{"", "", "port " + std::to_string(port) + " is out of range; expected 0..65535"};
    }
  }
  const uint32_t address = ntohl(bindAddr.s_addr);
  const bool loopback = (address >> 24) == 127;
  std::unique_ptr<UdpReceiver> r(new UdpReceiver());
  r->bindAddress_ = address;
  r->artNetUniverses_ = o.artNetUniverses;
  r->answerArtPoll_ = o.answerArtPoll;
  // Port 0 asks for a free port, which no one else holds.
  if (o.artNet && o.artNetPort != 0 && portTaken(address, o.artNetPort))
    r->notes_.push_back(sharedPortWarning(address, o.artNetPort, "Art-Net"));
  if (o.sacn && o.sacnPort != 0 && portTaken(address, o.sacnPort))
    r->notes_.push_back(sharedPortWarning(address, o.sacnPort, "sACN"));
  if (o.artNet) {
    auto fd = bindUdp(address, o.artNetPort, "Art-Net");
    if (!fd) return fd.error();
    r->sockets_.push_back({*fd, DmxProtocol::ArtNet});
    r->artNetPort_ = boundPort(*fd);
  }
  if (o.sacn) {
    auto fd = bindUdp(address, o.sacnPort, "sACN");
    if (!fd) return fd.error();
    r->sockets_.push_back({*fd, DmxProtocol::Sacn});
    r->sacnFd_ = *fd;
    r->sacnPort_ = boundPort(*fd);
    if (!loopback || o.multicast) {
      r->multicast_ = true;
      r->maxMulticastGroups_ = o.maxMulticastGroups;
      for (int universe : o.sacnUniverses) r->joinSacnUniverse(universe);
      // Universe discovery (E1.31 8) is sent to its own universe's group.
      r->joinSacnUniverse(kSacnDiscoveryUniverse, true);
    }
  }
  return r;
}

// A socket bound to a unicast address does not see multicast datagrams; one socket per group,
// bound to the group address itself, receives exactly that universe and nothing else, and the
// membership names the chosen interface. Bound to all addresses, the one socket joins.
bool UdpReceiver::joinSacnUniverse(int universe, bool beyondLimit) {
  if (!multicast_ || sacnPort_ == 0 || joinedUniverses_.count(universe)) return false;
  if (universe < 1 || (universe > 63999 && universe != kSacnDiscoveryUniverse)) return false;
  if (!beyondLimit && joinedData_ >= maxMulticastGroups_) {
    if (!noteLimit_) notes_.push_back("more than " + std::to_string(maxMulticastGroups_) +
                                      " sACN universes: the rest only by unicast");
    noteLimit_ = true;
    return false;
  }
  joinedUniverses_.insert(universe);
  const uint32_t group = sacnMulticastGroup(universe);
  const bool any = bindAddress_ == INADDR_ANY;
  int fd = sacnFd_;
  if (!any) {
    auto gfd = bindUdp(group, sacnPort_, "sACN multicast");
    if (!gfd) {
      notes_.push_back(gfd.error().message);
      return false;
    }
    fd = *gfd;
  }
  ip_mreq m{};
  m.imr_multiaddr.s_addr = htonl(group);
  m.imr_interface.s_addr = htonl(bindAddress_);
  if (setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &m, sizeof m) != 0) {
    notes_.push_back("cannot join " + ipString(group) + " on " + ipString(bindAddress_) + ": " + std::strerror(errno));
    if (!any) ::close(fd);
    return false;
  }
  if (!any) sockets_.push_back({fd, DmxProtocol::Sacn});
  if (!beyondLimit) ++joinedData_;
  const char* what = universe == kSacnDiscoveryUniverse ? " (sACN universe discovery)" : "";
  notes_.push_back("joined " + ipString(group) + (what[0] ? std::string(what) : " (sACN universe " + std::to_string(universe) + ")"));
  return true;
}

UdpReceiver::~UdpReceiver() {
  for (const Socket& s : sockets_) ::close(s.fd);
}

int UdpReceiver::pump(DmxInput& input, double nowS, int waitMs, int maxDatagrams) {
  if (sockets_.empty()) return 0;
  std::vector<pollfd> fds;
  for (const Socket& s : sockets_) fds.push_back({s.fd, POLLIN, 0});
  const int ready = ::poll(fds.data(), fds.size(), waitMs);
  if (ready <= 0) return 0;  // timeout, or EINTR from SIGINT: the caller's loop decides
  int read = 0;
  uint8_t buffer[2048];
  for (size_t i = 0; i < fds.size() && read < maxDatagrams; ++i) {
    if (!(fds[i].revents & POLLIN)) continue;
    while (read < maxDatagrams) {
      sockaddr_in from{};
      socklen_t fromLen = sizeof from;
      const ssize_t n = ::recvfrom(fds[i].fd, buffer, sizeof buffer, 0,
                                   reinterpret_cast<sockaddr*>(&from), &fromLen);
      if (n < 0) break;  // EAGAIN: drained (other errors: try again next pump)
      ++read;
      const std::span<const uint8_t> datagram(buffer, static_cast<size_t>(n));
      if (sockets_[i].protocol == DmxProtocol::ArtNet && answerArtPoll_ && isArtPoll(datagram))
        answerArtPoll(fds[i].fd, from);
      input.receive(sockets_[i].protocol, std::span<const uint8_t>(buffer, static_cast<size_t>(n)),
                    ntohl(from.sin_addr.s_addr), ntohs(from.sin_port), nowS);
    }
  }
  return read;
}

// Art-Net 4 unicasts the reply to the controller that polled; every console binds 6454, so its
// source port is where it listens. The IP field names the address the console reached: the
// bound one, or (bound to all) the local address of the route towards the console.
void UdpReceiver::answerArtPoll(int fd, const sockaddr_in& from) {
  ArtNodeInfo node;
  node.ipv4 = bindAddress_;
  if (node.ipv4 == INADDR_ANY) {
    const int probe = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_in local{};
    socklen_t len = sizeof local;
    if (probe >= 0 && ::connect(probe, reinterpret_cast<const sockaddr*>(&from), sizeof from) == 0 &&
        ::getsockname(probe, reinterpret_cast<sockaddr*>(&local), &len) == 0)
      node.ipv4 = ntohl(local.sin_addr.s_addr);
    if (probe >= 0) ::close(probe);
  }
  node.hazeUniverses = artNetUniverses_;
  for (const std::vector<uint8_t>& reply : artPollReplies(node))
    ::sendto(fd, reply.data(), reply.size(), 0, reinterpret_cast<const sockaddr*>(&from), sizeof from);
  ++artPollsAnswered_;
}

Result<std::unique_ptr<OscSocket>> OscSocket::open(const std::string& bindAddress, int port) {
  in_addr a{};
  if (inet_pton(AF_INET, bindAddress.c_str(), &a) != 1)
    return Error{"", "--bind", "'" + bindAddress + "' is not an IPv4 address; expected one like 127.0.0.1"};
  auto fd = bindUdp(ntohl(a.s_addr), port, "OSC");
  if (!fd) return fd.error();
  std::unique_ptr<OscSocket> s(new OscSocket());
  s->fd_ = *fd;
  s->port_ = boundPort(*fd);
  return s;
}

OscSocket::~OscSocket() {
  if (fd_ >= 0) ::close(fd_);
}

int OscSocket::pump(const std::function<std::vector<uint8_t>(std::span<const uint8_t>, const std::string&)>& handle,
                    int maxDatagrams) {
  int read = 0;
  std::vector<uint8_t> buffer(65536);
  while (read < maxDatagrams) {
    sockaddr_in from{};
    socklen_t fromLen = sizeof from;
    const ssize_t n = ::recvfrom(fd_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&from), &fromLen);
    if (n < 0) break;
    ++read;
    const std::string sender = ipString(ntohl(from.sin_addr.s_addr)) + ":" + std::to_string(ntohs(from.sin_port));
    const std::vector<uint8_t> reply = handle(std::span<const uint8_t>(buffer.data(), static_cast<size_t>(n)), sender);
    if (!reply.empty())
      ::sendto(fd_, reply.data(), reply.size(), 0, reinterpret_cast<const sockaddr*>(&from), sizeof from);
  }
  return read;
}

double LiveReceiver::nowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Result<std::unique_ptr<LiveReceiver>> LiveReceiver::open(const Show& show, const ProfileSet& profiles,
                                                         LiveOptions options) {
  if (options.udp.sacnUniverses.empty()) options.udp.sacnUniverses = patchedUniverses(show);
  if (options.udp.artNetUniverses.empty()) options.udp.artNetUniverses = patchedUniverses(show);
  auto udp = UdpReceiver::open(options.udp);
  if (!udp) return udp.error();
  std::unique_ptr<LiveReceiver> r(new LiveReceiver(show, profiles, options.input));
  r->udp_ = std::move(*udp);
  return r;
}

const StageState& LiveReceiver::poll(int waitMs) {
  udp_->pump(input_, nowS(), waitMs);
  // Whatever else arrived while the first batch was handled, without waiting again; bounded,
  // so a flood still lets the frame go on.
  for (int i = 0; i < 4 && udp_->pump(input_, nowS(), 0) > 0; ++i) {
  }
  // Synchronization packets go to the sync address's own group: join those data names, as
  // E1.31 receivers do (bounded by the gate's group limit).
  const std::vector<int>& sync = input_.syncGate().sacnSyncAddresses();
  for (; syncJoined_ < sync.size(); ++syncJoined_) udp_->joinSacnUniverse(sync[syncJoined_], true);
  return input_.poll(nowS());
}

double LiveReceiver::packetRate() const { return input_.packetRate(nowS()); }

}  // namespace haze
