# Writes a copy of a show whose venue and profiles name the original's files by absolute path,
# so the copy works from a temporary folder; the options change what a test needs changed.
# usage: python3 show_copy.py SRC DST [--scattering S] [--compact] [--spread-universes N]
import argparse, json, os

ap = argparse.ArgumentParser()
ap.add_argument('src')
ap.add_argument('dst')
ap.add_argument('--scattering', type=float)
ap.add_argument('--compact', action='store_true')
ap.add_argument('--spread-universes', type=int)
a = ap.parse_args()
show = json.load(open(a.src))
here = os.path.dirname(os.path.abspath(a.src))
show['venue']['gltf'] = os.path.join(here, show['venue']['gltf'])
show['profiles'] = {k: os.path.join(here, v) for k, v in show['profiles'].items()}
if a.scattering is not None:
    show['atmosphere']['scattering'] = a.scattering
if a.spread_universes:
    for i, f in enumerate(show['fixtures']):
        f['patch'] = {'universe': i % a.spread_universes + 1, 'address': 1 + 40 * (i // a.spread_universes)}
with open(a.dst, 'w') as out:
    json.dump(show, out, separators=(',', ':')) if a.compact else json.dump(show, out, indent=1)
