// Sends Art-Net ArtDmx to haze from the npm `artnet` package, an encoder independent of haze's.
// usage: node send_artnet.js PORT ROUNDS UNIVERSES_JSON
//   UNIVERSES_JSON: {"0": [255, 128, ...], "1": [...]}: Art-Net Port-Address -> values from
//   channel 1 (raw DMX). Every universe is sent in full once a round, a round every 100 ms,
//   unicast to 127.0.0.1; after round 5 (or the last) the script prints "ready".
'use strict';
const artnetFactory = require('artnet');

const [port, roundsArg, universesJson] = process.argv.slice(2);
if (!port || !roundsArg || !universesJson) {
  console.error('usage: node send_artnet.js PORT ROUNDS UNIVERSES_JSON');
  process.exit(2);
}
const universes = JSON.parse(universesJson);
const artnet = artnetFactory({ host: '127.0.0.1', port: Number(port), sendAll: true });
artnet.on('error', (e) => {
  console.error('send_artnet.js:', e.message);
  process.exit(1);
});

for (const [universe, values] of Object.entries(universes)) {
  artnet.set(Number(universe), 1, values);
}
const rounds = Number(roundsArg);
let round = 0;
const timer = setInterval(() => {
  ++round;
  for (const universe of Object.keys(universes)) artnet.send(Number(universe), true);
  if (round === Math.min(5, rounds)) process.stdout.write('ready\n');
  if (round >= rounds) {
    clearInterval(timer);
    // Let the last datagrams leave before the socket closes.
    setTimeout(() => artnet.close(), 100);
  }
}, 100);
