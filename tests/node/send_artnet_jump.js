// Sends Art-Net ArtDmx to haze from one socket (one source): first one look, then another, so
// haze sees a DMX jump from a single console (tests/cli/movement.sh).
// usage: node send_artnet_jump.js PORT ROUNDS_A UNIVERSES_A ROUNDS_B UNIVERSES_B
//   UNIVERSES_*: {"0": [255, 128, ...]}: Art-Net Port-Address -> values from channel 1. A round
//   every 100 ms; prints "jump" when the second look starts and "done" after the last round.
'use strict';
const artnetFactory = require('artnet');

const [port, roundsA, jsonA, roundsB, jsonB] = process.argv.slice(2);
if (!port || !roundsA || !jsonA || !roundsB || !jsonB) {
  console.error('usage: node send_artnet_jump.js PORT ROUNDS_A UNIVERSES_A ROUNDS_B UNIVERSES_B');
  process.exit(2);
}
const looks = [[Number(roundsA), JSON.parse(jsonA)], [Number(roundsB), JSON.parse(jsonB)]];
const artnet = artnetFactory({ host: '127.0.0.1', port: Number(port), sendAll: true });
artnet.on('error', (e) => {
  console.error('send_artnet_jump.js:', e.message);
  process.exit(1);
});

let look = 0, round = 0;
const set = (universes) => {
  for (const [universe, values] of Object.entries(universes)) artnet.set(Number(universe), 1, values);
};
set(looks[0][1]);
const timer = setInterval(() => {
  for (const universe of Object.keys(looks[look][1])) artnet.send(Number(universe), true);
  if (++round < looks[look][0]) return;
  round = 0;
  if (++look < looks.length) {
    set(looks[look][1]);
    process.stdout.write('jump\n');
    return;
  }
  clearInterval(timer);
  process.stdout.write('done\n');
  setTimeout(() => artnet.close(), 100);
}, 100);
