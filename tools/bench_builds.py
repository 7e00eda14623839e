#!/usr/bin/env python3
"""Compare haze builds, or one build with different options, in one run (docs/rendering.md, "Costs").

usage: tools/bench_builds.py [--rounds N] 'LABEL=HAZE [bench options]' ... -- BENCH OPTIONS

Each round runs `HAZE bench BENCH OPTIONS [its own options] --json` for every variant in turn, so
a machine whose load drifts slows every variant alike; it prints each variant's median frame,
surfaces and planes passes and CPU time per frame, and the median over rounds of its ratio to the
first variant (the figure that carries over to another machine). A build too old for an option
is the caller's to avoid: every variant gets the same BENCH OPTIONS.

It also prints the pixels each variant refined at full resolution, and says so when they differ:
the refinement walks again the pixels whose half-resolution scattering has detail, so a shader
change that adds noise or detail there adds refined pixels, and the frame's time then measures
both (a walk with one sample per chord measured as fast as the tree's, refining 17 % of the
pixels instead of 1.5 %). Time the walk alone with --refine 0 among the BENCH OPTIONS.
"""
import json
import shlex
import statistics
import subprocess
import sys


def bench(cmd, options):
    out = subprocess.run(cmd + ["bench"] + options + ["--json"], capture_output=True, text=True, timeout=1800)
    if out.returncode != 0:
        sys.exit(f"bench_builds: {' '.join(cmd)} bench failed ({out.returncode}): {out.stderr.strip()[-300:]}")
    d = json.loads(out.stdout[out.stdout.index("{"):])
    p = d.get("pass_ms", {})
    return (d["median_frame_ms"], p.get("surfaces", 0.0), p.get("planes", 0.0), d.get("median_frame_cpu_ms", 0.0),
            d.get("refined_pixels", 0))


def main(argv):
    rounds = 3
    if argv[:1] == ["--rounds"]:
        rounds, argv = int(argv[1]), argv[2:]
    if "--" not in argv:
        sys.exit(__doc__)
    cut = argv.index("--")
    variants = [v.split("=", 1) for v in argv[:cut]]
    options = argv[cut + 1:]
    if not variants or any(len(v) != 2 for v in variants):
        sys.exit(__doc__)
    runs = {label: [] for label, _ in variants}
    for _ in range(rounds):
        for label, cmd in variants:
            parts = shlex.split(cmd)
            runs[label].append(bench(parts[:1], options + parts[1:]))
    first = runs[variants[0][0]]
    print(f"{'variant':28s} {'frame ms':>9s} {'surfaces':>9s} {'planes':>9s} {'cpu ms':>9s} {'ratio':>6s} {'cpu ratio':>9s}"
          f" {'refined':>9s}")
    refined = {}
    for label, _ in variants:
        r = runs[label]
        med = [statistics.median(c) for c in zip(*r)]
        ratio = statistics.median(a[0] / b[0] for a, b in zip(r, first))
        cpu = statistics.median(a[3] / b[3] for a, b in zip(r, first) if b[3] > 0)
        refined[label] = int(med[4])
        print(f"{label:28s} {med[0]:9.1f} {med[1]:9.1f} {med[2]:9.1f} {med[3]:9.1f} {ratio:6.2f} {cpu:9.2f} {refined[label]:9d}")
    if len(set(refined.values())) > 1:
        print("note: the variants refined different numbers of pixels at full resolution; their frames time the "
              "refinement too (--refine 0 times the walk alone)")


if __name__ == "__main__":
    main(sys.argv[1:])
