// The soak's sender: sACN (the npm `sacn` encoder) on 8 universes at 44 Hz for SECONDS, with
// sources coming and going. "main" (priority 100) sends universes 1-8 throughout, its levels
// sweeping; "guest" (priority 120, so it wins while present) sends universes 1-4 for 3 s, then
// ends its streams (E1.31 stream-terminated) and is silent for 4 s; "flaky" (priority 100)
// sends universes 5-8 for 2 s, then simply stops (haze times it out) for 5 s. At the end it
// prints one JSON line: {"sent": datagrams, "terminated": those with the terminated bit}.
// usage: node soak_sacn.js PORT SECONDS
'use strict';
const { Sender, Packet } = require('sacn');

const [portArg, secondsArg] = process.argv.slice(2);
if (!portArg || !secondsArg) {
  console.error('usage: node soak_sacn.js PORT SECONDS');
  process.exit(2);
}
const port = Number(portArg);
const seconds = Number(secondsArg);
const rateHz = 44;

function source(name, cid, priority, universes) {
  return universes.map((universe) => new Sender({
    universe, port, useUnicastDestination: '127.0.0.1',
    defaultPacketOptions: { cid: Buffer.alloc(16, cid), sourceName: name, priority, useRawDmxValues: true },
  }));
}
const main = source('main', 1, 100, [1, 2, 3, 4, 5, 6, 7, 8]);
const guest = source('guest', 2, 120, [1, 2, 3, 4]);
const flaky = source('flaky', 3, 100, [5, 6, 7, 8]);

let sent = 0;
let terminated = 0;
async function send(senders, payload) {
  for (const s of senders) {
    await s.send({ payload });
    ++sent;
  }
}

// The npm encoder has no stream-terminated option: its packet with the Options bit 6 set
// (E1.31 6.2.6, byte 112 of the datagram), on the sender's own sequence and socket.
function terminate(sender) {
  const { buffer } = new Packet({ ...sender.defaultPacketOptions, payload: {}, universe: sender.universe,
                                  sequence: sender.sequence });
  sender.sequence = (sender.sequence + 1) % 256;
  buffer[112] |= 0x40;
  ++sent;
  return new Promise((resolve, reject) =>
    sender.socket.send(buffer, port, '127.0.0.1', (e) => (e ? reject(e) : resolve())));
}

async function run() {
  const start = Date.now();
  let frame = 0;
  let guestOn = false;
  for (;;) {
    const t = (Date.now() - start) / 1000;
    if (t >= seconds) break;
    const level = frame % 256;
    const payload = {};
    for (let a = 1; a <= 512; a += 7) payload[a] = (level + a) % 256;
    await send(main, payload);
    const guestPhase = t % 7;
    if (guestPhase < 3) {
      await send(guest, { 1: 255, 2: level });
      guestOn = true;
    } else if (guestOn) {
      // Leaving: E1.31 asks for three terminated packets per universe.
      for (let k = 0; k < 3; ++k) for (const g of guest) await terminate(g);
      terminated += 3 * guest.length;
      guestOn = false;
    }
    if (t % 7 < 2) await send(flaky, { 1: 128 });
    ++frame;
    // Keep the rate: the next frame is due at frame / rate, however long this one took.
    const due = start + (frame * 1000) / rateHz;
    await new Promise((r) => setTimeout(r, Math.max(0, due - Date.now())));
  }
  for (const s of [...main, ...guest, ...flaky]) s.close();
  process.stdout.write(JSON.stringify({ sent, terminated }) + '\n');
}

run().catch((e) => {
  console.error('soak_sacn.js:', e.message);
  process.exit(1);
});
