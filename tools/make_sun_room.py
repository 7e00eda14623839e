#!/usr/bin/env python3
"""Writes examples/demo/venue/sun_room.gltf: a closed 10 x 4 x 8 m room whose west wall (x = -5)
has a four-pane window, for the sun demo (examples/demo/sun.haze.json). Bare quads (the loader
makes flat normals), one buffer embedded as base64, three materials. Run from the repository
root; the output is deterministic."""
import base64
import json
import struct
import sys

X0, X1, Y1, Z0, Z1 = -5.0, 5.0, 4.0, -4.0, 4.0


def quads_to_mesh(quads):
    pos, idx = [], []
    for q in quads:
        base = len(pos)
        pos.extend(q)
        idx.extend([base, base + 1, base + 2, base, base + 2, base + 3])
    return pos, idx


def box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)],
        [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)],
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
        [(x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)],
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
    ]


def walls():
    q = [
        [(X0, Y1, Z0), (X1, Y1, Z0), (X1, Y1, Z1), (X0, Y1, Z1)],  # ceiling
        [(X1, 0, Z0), (X1, Y1, Z0), (X1, Y1, Z1), (X1, 0, Z1)],    # east
        [(X0, 0, Z1), (X1, 0, Z1), (X1, Y1, Z1), (X0, Y1, Z1)],    # south
        [(X0, 0, Z0), (X1, 0, Z0), (X1, Y1, Z0), (X0, Y1, Z0)],    # north
    ]
    # The west wall as a grid of cells; the four panes are left open.
    zs = [Z0, -1.5, -0.06, 0.06, 1.5, Z1]
    ys = [0.0, 1.2, 2.14, 2.26, 3.2, Y1]
    for i in range(len(zs) - 1):
        for j in range(len(ys) - 1):
            pane = i in (1, 3) and j in (1, 3)
            if not pane:
                a, b, c, d = zs[i], zs[i + 1], ys[j], ys[j + 1]
                q.append([(X0, c, a), (X0, d, a), (X0, d, b), (X0, c, b)])
    return q


def main(out):
    floor = [[(X0, 0, Z0), (X1, 0, Z0), (X1, 0, Z1), (X0, 0, Z1)]]
    parts = [("walls", walls(), 0), ("floor", floor, 1),
             ("plinth", box((-2.2, 0.0, -0.5), (-1.2, 0.9, 0.5)) + box((2.6, 0.0, 1.2), (3.0, 2.2, 1.6)), 2)]
    blob = b""
    accessors, views, prims = [], [], []
    for name, quads, material in parts:
        pos, idx = quads_to_mesh(quads)
        pbytes = b"".join(struct.pack("<3f", *p) for p in pos)
        ibytes = b"".join(struct.pack("<I", i) for i in idx)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(pbytes)})
        blob += pbytes
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(ibytes)})
        blob += ibytes
        lo = [min(p[k] for p in pos) for k in range(3)]
        hi = [max(p[k] for p in pos) for k in range(3)]
        accessors.append({"bufferView": len(views) - 2, "componentType": 5126, "count": len(pos), "type": "VEC3",
                          "min": lo, "max": hi})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": len(idx), "type": "SCALAR"})
        prims.append({"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1,
                      "material": material})
    gltf = {
        "asset": {"version": "2.0", "generator": "haze tools/make_sun_room.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "sun_room", "mesh": 0}],
        "meshes": [{"name": "sun_room", "primitives": prims}],
        "materials": [
            {"name": "plaster", "pbrMetallicRoughness": {"baseColorFactor": [0.55, 0.53, 0.5, 1]}},
            {"name": "boards", "pbrMetallicRoughness": {"baseColorFactor": [0.35, 0.24, 0.15, 1]}},
            {"name": "plinth", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.62, 1]}},
        ],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "examples/demo/venue/sun_room.gltf")
