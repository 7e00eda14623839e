// Checks a state JSON from `haze live --state-json` or `haze state --json` against wanted values.
// usage: node expect_state.js STATE.json WANT_JSON [TOLERANCE] [WHAT]
//   WANT_JSON: {"1": {"intensity": 0.8, "color": [0, 1, 1], "gobo": "Dots"}, ...}: fixture id ->
//   attributes. Numbers must be within TOLERANCE (default 1e-3), arrays element by element and of
//   the same length, strings equal. A fixture or attribute missing from the state is a failure.
//   Every difference is printed, prefixed with WHAT (default "fixture").
'use strict';
const fs = require('fs');

const [statePath, wantJson, tolArg, what] = process.argv.slice(2);
if (!statePath || !wantJson) {
  console.error('usage: node expect_state.js STATE.json WANT_JSON [TOLERANCE] [WHAT]');
  process.exit(2);
}
const state = JSON.parse(fs.readFileSync(statePath, 'utf8'));
const want = JSON.parse(wantJson);
const tol = tolArg === undefined ? 1e-3 : Number(tolArg);
const prefix = what || 'fixture';

const close = (got, v) => typeof got === 'number' && Math.abs(got - v) <= tol;
const matches = (got, v) => {
  if (Array.isArray(v)) return Array.isArray(got) && got.length === v.length && v.every((x, i) => matches(got[i], x));
  if (typeof v === 'number') return close(got, v);
  return got === v;
};

let bad = 0;
for (const [id, attrs] of Object.entries(want)) {
  if (!state[id]) {
    console.error(prefix + ' ' + id + ' missing from ' + statePath);
    ++bad;
    continue;
  }
  for (const [k, v] of Object.entries(attrs)) {
    const got = state[id][k];
    if (!matches(got, v)) {
      console.error(prefix + ' ' + id + ' ' + k + ': got ' + JSON.stringify(got) + ', want ' + JSON.stringify(v));
      ++bad;
    }
  }
}
if (Object.keys(want).length === 0) {
  console.error('expect_state.js: nothing to compare');
  bad = 1;
}
process.exit(bad ? 1 : 0);
