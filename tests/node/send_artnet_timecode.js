// Sends Art-Net ArtTimeCode (OpCode 0x9700), written byte by byte from the Art-Net 4 table,
// independently of haze's parser: EBU 25 fps, one packet a frame (40 ms), unicast to 127.0.0.1.
// usage: node send_artnet_timecode.js PORT RUN...   RUN = START_TIMECODE+FRAMES, e.g.
//   00:00:00:00+80 00:00:01:12+20   (80 frames from 0, then a jump back to 1 s 12 frames)
// Prints "ready" after the last packet.
'use strict';
const dgram = require('dgram');

const [port, ...runs] = process.argv.slice(2);
if (!port || runs.length === 0) {
  console.error('usage: node send_artnet_timecode.js PORT HH:MM:SS:FF+FRAMES...');
  process.exit(2);
}
const fps = 25;

function packet(total) {
  const f = total % fps, s = Math.floor(total / fps) % 60, m = Math.floor(total / (fps * 60)) % 60,
        h = Math.floor(total / (fps * 3600));
  const b = Buffer.alloc(19);
  b.write('Art-Net\0', 0, 'latin1');
  b.writeUInt16LE(0x9700, 8);  // OpCode, low byte first
  b.writeUInt16BE(14, 10);     // ProtVer
  b[14] = f; b[15] = s; b[16] = m; b[17] = h;
  b[18] = 1;                   // EBU, 25 fps
  return b;
}

const socket = dgram.createSocket('udp4');
async function main() {
  for (const run of runs) {
    const [start, count] = run.split('+');
    const [h, m, s, f] = start.split(':').map(Number);
    let total = ((h * 60 + m) * 60 + s) * fps + f;
    for (let k = 0; k < Number(count); ++k, ++total) {
      await new Promise((res, rej) => socket.send(packet(total), Number(port), '127.0.0.1', (e) => (e ? rej(e) : res())));
      await new Promise((res) => setTimeout(res, 1000 / fps));
    }
  }
  process.stdout.write('ready\n');
  socket.close();
}
main().catch((e) => {
  console.error('send_artnet_timecode.js:', e.message);
  process.exit(1);
});
