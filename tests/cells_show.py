#!/usr/bin/env python3
"""A show of one multi-cell wash (tests/cli/cells_auto.sh, tests/gui/view_cells.sh): fixture 1 at
5 m, aimed down, seen from the Cube venue's front, with cue 1's values for it.

usage: cells_show.py OUT.haze.json PROFILE VENUE [VALUES_JSON]   (values default: {"intensity": 1})
"""
import json
import sys

if len(sys.argv) not in (4, 5):
    sys.exit(__doc__)
out, profile, venue = sys.argv[1:4]
values = json.loads(sys.argv[4]) if len(sys.argv) == 5 else {"intensity": 1}
json.dump({"format": "haze-show", "version": 1, "venue": {"gltf": venue},
           "atmosphere": {"scattering": 0.05, "absorption": 0.0, "phase": "hazy", "g": 0.0, "ambient": 0.05},
           "cameras": [{"name": "FOH", "position": [0, 3, 12], "target": [0, 1, 0], "fov_y": 50}],
           "profiles": {"w": profile}, "fixtures": [{"id": 1, "name": "wash", "profile": "w", "position": [0, 5, 0]}],
           "cue_lists": [{"name": "Main", "cues": [{"number": "1", "values": {"1": values}}]}]},
          open(out, "w"))
