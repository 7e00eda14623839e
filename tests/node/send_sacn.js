// Sends sACN (E1.31) to haze from the npm `sacn` package, an encoder independent of haze's.
// usage: node send_sacn.js PORT ROUNDS STREAMS_JSON [BAD_PACKETS] [multicast]
//   STREAMS_JSON: [{"universe": 1, "priority": 100, "cid": 1, "name": "main",
//                   "slots": {"1": 255, "2": 128}}, ...]  (raw DMX values, unicast to 127.0.0.1)
//   Every stream is sent once a round, a round every 100 ms; after round 10 (or the last) the
//   script prints "ready" so a test knows levels have arrived. BAD_PACKETS datagrams with an
//   out-of-range priority (250) are sent once at the start, for the malformed counters.
//   With "multicast" the streams go to their groups 239.255.hi.lo through the loopback
//   interface instead of unicast to 127.0.0.1. SACN_HOST=ADDR unicasts to another loopback
//   address (a GUI test's haze on --bind ADDR, port 5568).
'use strict';
const dgram = require('dgram');
const { Sender, Packet } = require('sacn');

const [port, roundsArg, streamsJson, badArg, mode] = process.argv.slice(2);
const multicast = mode === 'multicast';
if (!port || !roundsArg || !streamsJson) {
  console.error('usage: node send_sacn.js PORT ROUNDS STREAMS_JSON [BAD_PACKETS]');
  process.exit(2);
}
const streams = JSON.parse(streamsJson);
const bad = Number(badArg || 0);
const host = process.env.SACN_HOST || '127.0.0.1';

const senders = streams.map((s) => {
  const cid = Buffer.alloc(16, s.cid || 1);
  return {
    sender: new Sender({
      universe: s.universe,
      port: Number(port),
      useUnicastDestination: multicast ? undefined : host,
      defaultPacketOptions: { cid, sourceName: s.name || 'haze test', priority: s.priority || 100,
                              useRawDmxValues: true },
    }),
    payload: s.slots,
  };
});

async function main() {
  if (multicast) {
    for (const s of senders) {
      await new Promise((resolve) => s.sender.socket.bind(0, '127.0.0.1', resolve));
      s.sender.socket.setMulticastInterface('127.0.0.1');
    }
  }
  if (bad > 0) {
    const socket = dgram.createSocket('udp4');
    const buffer = new Packet({ universe: 1, sequence: 0, payload: {}, sourceName: 'bad',
                                priority: 100, cid: Buffer.alloc(16, 0xEE) }).buffer;
    buffer[108] = 250;  // E1.31 priorities stop at 200
    for (let i = 0; i < bad; ++i) {
      await new Promise((resolve, reject) =>
        socket.send(buffer, Number(port), host, (e) => (e ? reject(e) : resolve())));
    }
    socket.close();
  }
  const rounds = Number(roundsArg);
  for (let round = 1; round <= rounds; ++round) {
    for (const s of senders) await s.sender.send({ payload: s.payload });
    if (round === Math.min(10, rounds)) process.stdout.write('ready\n');
    await new Promise((r) => setTimeout(r, 100));
  }
  for (const s of senders) s.sender.close();
}

main().catch((e) => {
  console.error('send_sacn.js:', e.message);
  process.exit(1);
});
