// The socket side of DMX input: POSIX UDP sockets for Art-Net (6454) and sACN (5568), bound only
// to the address given (default 127.0.0.1, loopback: nothing off this machine can reach haze
// unless the user says so). sACN multicast groups 239.255.hi.lo are joined for the show's
// universes when bound to a non-loopback address, or when asked. LiveReceiver wraps sockets and
// a DmxInput into the object the GUI polls once a frame.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include <netinet/in.h>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/dmx/dmx_input.h"

namespace haze {

struct UdpReceiverOptions {
  std::string bindAddress = "127.0.0.1";  // an IPv4 address of this machine; "0.0.0.0" = all
  bool artNet = true;
  bool sacn = true;
  int artNetPort = 6454;  // 0 = any free port (tests); see UdpReceiver::artNetPort()
  int sacnPort = 5568;
  bool multicast = false;          // join the sACN groups even on loopback
  std::set<int> sacnUniverses;     // groups to join (the show's patched universes)
  std::set<int> artNetUniverses;   // the output ports an ArtPollReply lists (the patched universes)
  bool answerArtPoll = true;       // reply to consoles' ArtPoll, so they send to haze
  int maxMulticastGroups = 64;     // at most this many universes joined
};

class UdpReceiver {
 public:
  static Result<std::unique_ptr<UdpReceiver>> open(const UdpReceiverOptions& options);
  ~UdpReceiver();
  UdpReceiver(const UdpReceiver&) = delete;
  UdpReceiver& operator=(const UdpReceiver&) = delete;

  // Waits up to waitMs for a datagram, then hands every pending one (at most maxDatagrams) to
  // input, stamped with nowS. Returns how many were read.
  int pump(DmxInput& input, double nowS, int waitMs, int maxDatagrams = 4096);

  int artNetPort() const { return artNetPort_; }  // the bound ports (0 when not listening)
  int sacnPort() const { return sacnPort_; }
  const std::vector<std::string>& notes() const { return notes_; }  // "joined 239.255.0.1"...
  int artPollsAnswered() const { return artPollsAnswered_; }
  // Joins an sACN universe's multicast group when listening for multicast (at most
  // maxMulticastGroups data universes, unless beyondLimit: sync and discovery universes).
  bool joinSacnUniverse(int universe, bool beyondLimit = false);

 private:
  UdpReceiver() = default;
  struct Socket {
    int fd = -1;
    DmxProtocol protocol = DmxProtocol::Sacn;
  };
  std::vector<Socket> sockets_;
  int artNetPort_ = 0;
  int sacnPort_ = 0;
  std::vector<std::string> notes_;
  uint32_t bindAddress_ = 0;  // host order
  std::set<int> artNetUniverses_;
  bool answerArtPoll_ = true;
  int artPollsAnswered_ = 0;
  bool multicast_ = false;
  int sacnFd_ = -1;
  int maxMulticastGroups_ = 64;
  int joinedData_ = 0;
  bool noteLimit_ = false;
  std::set<int> joinedUniverses_;

  void answerArtPoll(int fd, const sockaddr_in& from);
};

// The OSC remote-control socket (shows/dmx/osc_command.h): bound like the DMX sockets, only to
// the address given; every command gets its reply sent back to the address it came from.
class OscSocket {
 public:
  static Result<std::unique_ptr<OscSocket>> open(const std::string& bindAddress, int port);
  ~OscSocket();
  OscSocket(const OscSocket&) = delete;
  OscSocket& operator=(const OscSocket&) = delete;
  // Reads what is pending (at most maxDatagrams, no waiting) and hands each to `handle` with the
  // sender as "a.b.c.d:port"; what `handle` returns is sent back unless empty.
  int pump(const std::function<std::vector<uint8_t>(std::span<const uint8_t>, const std::string&)>& handle,
           int maxDatagrams = 256);
  int port() const { return port_; }

 private:
  OscSocket() = default;
  int fd_ = -1;
  int port_ = 0;
};

struct LiveOptions {
  UdpReceiverOptions udp;  // udp.sacnUniverses is filled from the show when left empty
  DmxInputOptions input;
};

// Sockets + DmxInput on the steady clock: poll() once a frame.
class LiveReceiver {
 public:
  // show and profiles must outlive the receiver.
  static Result<std::unique_ptr<LiveReceiver>> open(const Show& show, const ProfileSet& profiles,
                                                    LiveOptions options);
  // Reads what arrived (waiting up to waitMs for the first datagram) and returns the state.
  const StageState& poll(int waitMs = 0);

  const StageState& state() const { return input_.state(); }
  DmxInput& input() { return input_; }
  std::vector<DmxSourceInfo> sources() const { return input_.sources(); }
  const DmxInputStats& stats() const { return input_.stats(); }
  double packetRate() const;  // good packets per second over the last second
  const UdpReceiver& udp() const { return *udp_; }
  const DmxInput& input() const { return input_; }
  static double nowS();  // the steady clock, in seconds

 private:
  LiveReceiver(const Show& show, const ProfileSet& profiles, const DmxInputOptions& options)
      : input_(show, profiles, options) {}
  DmxInput input_;
  std::unique_ptr<UdpReceiver> udp_;
  size_t syncJoined_ = 0;  // sync addresses already handed to joinSacnUniverse
};

}  // namespace haze
