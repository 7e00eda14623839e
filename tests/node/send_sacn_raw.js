// Sends the E1.31 packets the npm `sacn` package cannot: data packets with a Synchronization
// Address or per-slot priorities (START code 0xDD), Synchronization Packets and Universe
// Discovery Packets. Each packet is written byte by byte from E1.31-2018 tables 4-1, 4-2 and
// 4-3 here, independently of haze's parser.
// usage: node send_sacn_raw.js PORT ROUNDS STEPS_JSON [FINAL_STEPS_JSON]
//   STEPS_JSON: one round, a list of steps, sent ROUNDS times 40 ms apart; FINAL_STEPS_JSON is
//   sent once after them. Then the script prints "ready" and keeps the socket quiet for 3 s.
//   {"data": {"universe": 1, "cid": 1, "name": "desk", "priority": 100, "sync": 7000,
//             "options": 32, "start": 0, "slots": {"1": 255}}}   (slots: raw values from 1)
//   {"sync": {"address": 7000, "cid": 1}}
//   {"discovery": {"cid": 1, "name": "desk", "page": 0, "last": 0, "universes": [1, 2]}}
//   Sequence numbers count per CID and universe (sync packets: per CID and address).
//   Everything goes unicast to 127.0.0.1:PORT.
'use strict';
const dgram = require('dgram');

const [port, roundsArg, stepsJson, finalJson] = process.argv.slice(2);
if (!port || !roundsArg || !stepsJson) {
  console.error('usage: node send_sacn_raw.js PORT ROUNDS STEPS_JSON [FINAL_STEPS_JSON]');
  process.exit(2);
}
const steps = JSON.parse(stepsJson);
const finalSteps = finalJson ? JSON.parse(finalJson) : [];
const sequences = new Map();
function nextSequence(key) {
  const s = ((sequences.get(key) ?? 255) + 1) & 0xff;
  sequences.set(key, s);
  return s;
}

function flagsLength(buf, at) {
  buf.writeUInt16BE(0x7000 | (buf.length - at), at);
}

// Root layer: preamble 0x0010, post-amble 0, "ASC-E1.17\0\0\0", flags & length, vector, CID.
function root(size, vector, cid) {
  const b = Buffer.alloc(size);
  b.writeUInt16BE(0x0010, 0);
  b.writeUInt16BE(0x0000, 2);
  b.write('ASC-E1.17\0\0\0', 4, 'latin1');
  flagsLength(b, 16);
  b.writeUInt32BE(vector, 18);
  Buffer.alloc(16, cid).copy(b, 22);
  flagsLength(b, 38);
  return b;
}

function dataPacket(d) {
  const values = [];
  for (const [slot, v] of Object.entries(d.slots || {})) values[Number(slot) - 1] = v;
  const count = Math.max(values.length, 1);
  const b = root(126 + count, 0x00000004, d.cid || 1);
  b.writeUInt32BE(0x00000002, 40);              // VECTOR_E131_DATA_PACKET
  b.write((d.name || 'raw sender').slice(0, 63), 44, 'utf8');
  b[108] = d.priority ?? 100;
  b.writeUInt16BE(d.sync || 0, 109);
  b[111] = nextSequence(`d${d.cid || 1}/${d.universe}`);
  b[112] = d.options || 0;
  b.writeUInt16BE(d.universe, 113);
  flagsLength(b, 115);
  b[117] = 0x02;                                // VECTOR_DMP_SET_PROPERTY
  b[118] = 0xa1;
  b.writeUInt16BE(0x0000, 119);
  b.writeUInt16BE(0x0001, 121);
  b.writeUInt16BE(count + 1, 123);
  b[125] = d.start || 0;
  for (let i = 0; i < count; ++i) b[126 + i] = values[i] || 0;
  return b;
}

function syncPacket(s) {
  const b = root(49, 0x00000008, s.cid || 1);
  b.writeUInt32BE(0x00000001, 40);              // VECTOR_E131_EXTENDED_SYNCHRONIZATION
  b[44] = nextSequence(`s${s.cid || 1}/${s.address}`);
  b.writeUInt16BE(s.address, 45);
  return b;
}

function discoveryPacket(d) {
  const universes = d.universes || [];
  const b = root(120 + 2 * universes.length, 0x00000008, d.cid || 1);
  b.writeUInt32BE(0x00000002, 40);              // VECTOR_E131_EXTENDED_DISCOVERY
  b.write((d.name || 'raw sender').slice(0, 63), 44, 'utf8');
  flagsLength(b, 112);
  b.writeUInt32BE(0x00000001, 114);             // VECTOR_UNIVERSE_DISCOVERY_UNIVERSE_LIST
  b[118] = d.page || 0;
  b[119] = d.last || 0;
  universes.forEach((u, i) => b.writeUInt16BE(u, 120 + 2 * i));
  return b;
}

function encode(step) {
  if (step.data) return dataPacket(step.data);
  if (step.sync) return syncPacket(step.sync);
  if (step.discovery) return discoveryPacket(step.discovery);
  throw new Error('unknown step ' + JSON.stringify(step));
}

const socket = dgram.createSocket('udp4');
function send(buf) {
  return new Promise((resolve, reject) =>
    socket.send(buf, Number(port), '127.0.0.1', (e) => (e ? reject(e) : resolve())));
}

async function main() {
  const rounds = Number(roundsArg);
  for (let r = 0; r < rounds; ++r) {
    for (const step of steps) await send(encode(step));
    await new Promise((res) => setTimeout(res, 40));
  }
  for (const step of finalSteps) await send(encode(step));
  process.stdout.write('ready\n');
  await new Promise((res) => setTimeout(res, 3000));
  socket.close();
}

main().catch((e) => {
  console.error('send_sacn_raw.js:', e.message);
  process.exit(1);
});
