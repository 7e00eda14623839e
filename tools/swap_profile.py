#!/usr/bin/env python3
"""Every fixture of a show swapped to one GDTF profile, re-patched in its mode's footprint.

The bodies' cost (docs/rendering.md, "Fixture bodies") is measured on the Capture demo rig with
every fixture a BMFL:
    haze import-mvr ../shared/data/gdtf/mvr/capture_demo_show.mvr -o /tmp/cap/capture.haze.json
    tools/swap_profile.py /tmp/cap/capture.haze.json "../shared/data/gdtf/Robe lighting s.r.o.@BMFL Spot@cannot assign 0 to frost function.gdtf" \\
        "Mode 1 - Standard 16 bit" 42 /tmp/cap/capture_bmfl.haze.json
    haze bench --show /tmp/cap/capture_bmfl.haze.json --width 960 --height 540 --frames 8 --compare-bodies
"""
import json
import os
import shutil
import sys


def main():
    if len(sys.argv) != 6:
        sys.exit("usage: swap_profile.py SHOW.json PROFILE.gdtf MODE FOOTPRINT OUT.json")
    show, gdtf, mode, footprint, out = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
    with open(show) as f:
        d = json.load(f)
    # The profile beside the output, named relative to it as the importer does.
    name = "swapped.gdtf"
    shutil.copyfile(gdtf, os.path.join(os.path.dirname(os.path.abspath(out)), name))
    d["profiles"] = {"swapped": name}
    per_universe = 512 // footprint
    for i, fixture in enumerate(d["fixtures"]):
        fixture["profile"] = "swapped"
        fixture["mode"] = mode
        fixture["patch"] = {"universe": 1 + i // per_universe, "address": 1 + (i % per_universe) * footprint}
    with open(out, "w") as f:
        json.dump(d, f, indent=1)


if __name__ == "__main__":
    main()
