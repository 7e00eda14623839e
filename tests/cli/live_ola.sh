#!/usr/bin/env bash
# haze live driven by the Open Lighting Architecture (Debian's `ola`), a second, independent
# DMX sender: values set with ola_set_dmx reach `haze live --state-json` over E1.31 (multicast)
# and over Art-Net (OLA sends ArtDmx only to nodes that answered its ArtPoll, so this also
# proves haze's ArtPollReply works for a real controller).
#
# olad refuses to run as root and its E1.31 plugin never sends on a loopback interface, so olad
# runs as the `olad` user in a network namespace of its own, joined by a veth pair (the
# loopback-range addresses 127.77.0.1 and .2, no physical interface) to a second namespace that
# runs haze. Needs root, `ip netns`, olad, ola_set_dmx, ola_patch, setpriv and python3; without
# them it exits 77 (skipped) and says why. Expected values are worked out by hand below (the same frame as tests/cli/live_sacn.sh).
# usage: bash live_ola.sh HAZE_BINARY REPO_ROOT
source "$(dirname "$0")/live_session.bash" "$@"

skip() {
  echo "SKIP live_ola: $*"
  exit 77
}
[ "$(id -u)" -eq 0 ] || skip "needs root for network namespaces"
for tool in ip olad ola_set_dmx ola_patch ola_dev_info setpriv python3 node; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (tools/install-deps.sh installs ola)"
done
id olad >/dev/null 2>&1 || skip "no olad user (Debian's ola package creates it)"

NS_OLA=hzola$$
NS_HAZE=hzhaze$$
OLA_IP=127.77.0.1
HAZE_IP=127.77.0.2
ip netns add "$NS_OLA" 2>/dev/null || skip "cannot create a network namespace (ip netns add failed)"
cleanup() {
  local ns pid
  for ns in "$NS_OLA" "$NS_HAZE"; do
    for pid in $(ip netns pids "$ns" 2>/dev/null); do kill "$pid" 2>/dev/null; done
  done
  sleep 0.2
  ip netns del "$NS_OLA" 2>/dev/null
  ip netns del "$NS_HAZE" 2>/dev/null
  _live_cleanup
}
trap cleanup EXIT
ip netns add "$NS_HAZE" || fail "cannot create a second network namespace"
ip link add "vo$$" type veth peer name "vh$$" || skip "cannot create a veth pair"
ip link set "vo$$" netns "$NS_OLA" && ip link set "vh$$" netns "$NS_HAZE" || fail "cannot move the veth ends"
# The veth pair carries 127.77.0.0/24, so nothing here can reach a real network. Two things make
# a loopback-range address work off `lo`: route_localnet (the kernel otherwise drops such packets
# as martians), and `lo` holding only 127.0.0.1/32 instead of 127.0.0.0/8 (whose local route
# would claim the peer's address as this namespace's own). olad's RPC stays on 127.0.0.1.
# "brd +": OLA's ArtPoll goes to the interface's broadcast address (127.77.0.255), which must exist.
for end in "$NS_OLA:vo$$:$OLA_IP" "$NS_HAZE:vh$$:$HAZE_IP"; do
  IFS=: read -r ns dev addr <<<"$end"
  ip -n "$ns" link set lo up && ip -n "$ns" addr del 127.0.0.1/8 dev lo &&
    ip -n "$ns" addr add 127.0.0.1/32 dev lo || fail "cannot narrow lo to 127.0.0.1 in $ns"
  ip netns exec "$ns" sysctl -qw net.ipv4.conf.all.route_localnet=1 "net.ipv4.conf.$dev.route_localnet=1" ||
    fail "cannot set route_localnet in $ns"
  ip -n "$ns" addr add "$addr/24" brd + dev "$dev" && ip -n "$ns" link set "$dev" up &&
    ip -n "$ns" route add 224.0.0.0/4 dev "$dev" || fail "cannot bring up $dev in $ns"
done

# olad's configuration: only the E1.31 and Art-Net plugins, on the veth address, one output
# port each. A plugin without a config file would be enabled with its defaults.
CONF="$TMP/olad"
mkdir "$CONF"
for plugin in artnet dummy dmx4linux e131 espnet ftdidmx gpio karate kinet milinst nanoleaf \
  opendmx openpixelcontrol osc pathport renard sandnet shownet spi stageprofi uartdmx usbdmx usbserial; do
  echo "enabled = false" >"$CONF/ola-$plugin.conf"
done
printf 'enabled = true\nip = %s\ninput_ports = 0\noutput_ports = 1\nprepend_hostname = false\n' \
  "$OLA_IP" >"$CONF/ola-e131.conf"
printf 'enabled = true\nip = %s\noutput_ports = 1\nnet = 0\nsubnet = 0\nshort_name = OLA\nlong_name = OLA test\n' \
  "$OLA_IP" >"$CONF/ola-artnet.conf"
chmod 711 "$TMP"
chown -R olad "$CONF"
ola() { ip netns exec "$NS_OLA" "$@"; }
ola setpriv --reuid=olad --regid=nogroup --clear-groups \
  olad -c "$CONF" --no-http --no-register-with-dns-sd -l 2 >"$TMP/olad.log" 2>&1 &
devices=""
for _ in $(seq 100); do
  devices=$(ola ola_dev_info 2>/dev/null)
  echo "$devices" | grep -q "E1.31" && echo "$devices" | grep -q "ArtNet" && break
  sleep 0.1
done
e131_dev=$(echo "$devices" | sed -n 's/^Device \([0-9]*\): E1.31.*/\1/p')
artnet_dev=$(echo "$devices" | sed -n 's/^Device \([0-9]*\): ArtNet.*/\1/p')
[ -n "$e131_dev" ] && [ -n "$artnet_dev" ] || fail "olad did not start its E1.31 and Art-Net devices: $(cat "$TMP/olad.log")"
# OLA universe 1 -> sACN universe 1 (haze universe 1); OLA universe 16 -> Art-Net Port-Address
# 0:0:0 (OLA takes the universe number modulo 16), which is haze universe 1 too.
ola ola_patch -d "$e131_dev" -p 0 -u 1 && ola ola_patch -d "$artnet_dev" -p 0 -u 16 || fail "ola_patch failed"

# A listener of our own beside haze's Art-Net socket (both SO_REUSEPORT, so a broadcast reaches
# both) tells when OLA's ArtPoll (every 10 s while it sends) has come.
ip netns exec "$NS_HAZE" python3 - "$TMP/polled" <<'PY' &
import socket, sys
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
s.bind(('0.0.0.0', 6454))
s.settimeout(20)
while True:
    data, _ = s.recvfrom(2048)
    if data[:8] == b'Art-Net\0' and data[8:10] == b'\x00\x20':
        open(sys.argv[1], 'w').close()
        break
PY
POLL_PID=$!

printf '#!/bin/sh\nexec ip netns exec %s "%s" "$@"\n' "$NS_HAZE" "$HAZE" >"$TMP/haze-in-ns"
chmod +x "$TMP/haze-in-ns"
HAZE="$TMP/haze-in-ns"
SHOW="$ROOT/tests/data/live/live.haze.json"

# Art-Net: OLA broadcasts its ArtPoll to 127.77.0.255, which a socket bound to one address does
# not receive, so this haze binds 0.0.0.0 (docs/live.md, "Network"); it runs while sACN is tested.
live_start Art-Net "$SHOW" --artnet --bind 0.0.0.0 --movement instant --state-json "$TMP/artnet.json"
ARTNET_PID=$HAZE_PID
ARTNET_ERR=$HAZE_ERR

# E1.31 multicast: haze on the veth address with --multicast.
live_start sACN "$SHOW" --sacn --bind "$HAZE_IP" --multicast --movement instant --state-json "$TMP/sacn.json"
for _ in $(seq 100); do
  grep -q "joined 239.255.0.1 " "$HAZE_ERR" && break
  sleep 0.1
done
grep -q "joined 239.255.0.1 " "$HAZE_ERR" || fail "haze did not join sACN universe 1's group"
# Dimmer, Pan, Pan fine, Tilt, Tilt fine, C, M, Y, Gobo, Zoom (fixture 1 at address 1).
# OLA sends a frame when it is set (no refresh), so it is set three times.
for _ in 1 2 3; do
  ola ola_set_dmx -u 1 -d 255,192,0,64,0,0,255,0,150,128 || fail "ola_set_dmx failed"
  sleep 0.2
done
live_stop_ok
grep -q 'source sACN .* universe 1 priority 100' "$HAZE_ERR" || fail "OLA's E1.31 source is not listed"
# Pan 0xC000: -270 + 540 * 49152 / 65535 = 135.00618; tilt 0x4000: -135 + 270 * 16384 / 65535
# = -67.49897; magenta full: [1, 0, 1]; gobo 150: Stars; zoom 128: 8 + 32 * 128 / 255 = 24.06275.
expect_state "$TMP/sacn.json" '{
  "1": {"intensity": 1, "pan": 135.00618, "tilt": -67.49897, "color": [1, 0, 1], "zoom": 24.06275, "gobo": "Stars"}
}' 1e-3 "E1.31: fixture" || fail "fixture 1 over E1.31 differs from what OLA was set to"

HAZE_PID=$ARTNET_PID
HAZE_ERR=$ARTNET_ERR
wait "$POLL_PID" 2>/dev/null
[ -f "$TMP/polled" ] || fail "OLA sent no ArtPoll within 20 s"
sleep 0.3  # OLA takes haze's ArtPollReply in
# Dimmer 128, pan 0x4000, tilt 0xC000, cyan 255 and yellow 51, gobo 0, zoom 255.
for _ in 1 2 3; do
  ola ola_set_dmx -u 16 -d 128,64,0,192,0,255,0,51,0,255 || fail "ola_set_dmx failed"
  sleep 0.2
done
live_stop_ok
grep -q "answered [1-9][0-9]* ArtPoll" "$HAZE_ERR" || fail "haze answered no ArtPoll"
grep -q "source Art-Net $OLA_IP" "$HAZE_ERR" || fail "OLA is not listed as an Art-Net source"
# Intensity 128/255 = 0.50196; pan 0x4000: -270 + 540 * 16384 / 65535 = -134.99794; tilt
# 0xC000: -135 + 270 * 49152 / 65535 = 67.50309; colour (1 - 1, 1 - 0, 1 - 0.2) = [0, 1, 0.8];
# gobo 0: Open; zoom 255: 40.
expect_state "$TMP/artnet.json" '{
  "1": {"intensity": 0.50196, "pan": -134.99794, "tilt": 67.50309, "color": [0, 1, 0.8], "zoom": 40, "gobo": "Open"}
}' 1e-3 "Art-Net: fixture" || fail "fixture 1 over Art-Net differs from what OLA was set to"
echo "PASS live_ola"
