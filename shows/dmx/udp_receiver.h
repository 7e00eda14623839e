// The socket side of DMX input: POSIX UDP sockets for Art-Net (6454) and sACN (5568), bound only
// to the address given (default 127.0.0.1, loopback: nothing off this machine can reach haze
// unless the user says so). sACN multicast groups 239.255.hi.lo are joined for the show's
// universes when bound to a non-loopback address, or when asked. LiveReceiver wraps sockets and
// a DmxInput into the object the GUI polls once a frame.
#pragma once

#include <cstdint>

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

  void answerArtPoll(int fd, const sockaddr_in& from);
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
  std::vector<DmxSourceInfo> sources() const { return input_.sources(); }
  const DmxInputStats& stats() const { return input_.stats(); }
  double packetRate() const;  // good packets per second over the last second
  const UdpReceiver& udp() const { return *udp_; }
  static double nowS();  // the steady clock, in seconds

 private:
  LiveReceiver(const Show& show, const ProfileSet& profiles, const DmxInputOptions& options)
      : input_(show, profiles, options) {}
  DmxInput input_;
  std::unique_ptr<UdpReceiver> udp_;
};

}  // namespace haze
