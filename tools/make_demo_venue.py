#!/usr/bin/env python3
# Generates the bundled demo show (examples/demo): the theatre venue as glTF 2.0 (.gltf + .bin +
# a deck texture), the gobo images, the native fixture profiles and demo.haze.json with pan/tilt
# computed from named targets by docs/physics.md's convention. Standard library only; run by hand
# (`python3 tools/make_demo_venue.py`), the output is committed. It re-reads what it wrote and
# checks it (accessor sizes, bounds, indices, patch overlaps, value ranges) and ray-casts every
# beam axis of every cue against the venue's triangles, so a wrong aim or a broken file fails here
# rather than in a render.
import json
import math
import os
import random
import struct
import sys
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEMO = os.path.join(ROOT, "examples", "demo")

# --------------------------------------------------------------------------------------------
# PNG writing (zlib + struct): 8-bit greyscale (colour type 0) or RGB (colour type 2).


def png_bytes(width, height, rows, channels):
    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))
    colour_type = {1: 0, 3: 2}[channels]
    raw = b"".join(b"\x00" + bytes(r) for r in rows)  # filter type 0 on every row
    assert all(len(r) == width * channels for r in rows), "PNG row of the wrong length"
    return (b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def write_png(path, width, height, rows, channels):
    with open(path, "wb") as f:
        f.write(png_bytes(width, height, rows, channels))


def read_png_size(path):
    with open(path, "rb") as f:
        head = f.read(33)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", path
    return struct.unpack(">II", head[16:24])


def clamp01(x):
    return 0.0 if x < 0.0 else 1.0 if x > 1.0 else x


# Gobos: luminance, 255 passes, 0 blocks. Drawn with 4x4 supersampling so edges are smooth at
# the resolution the light map samples them. Only the unit disc matters (the gate blocks the rest).
GOBO_SIZE = 256


def gobo_image(inside, size=GOBO_SIZE, ss=4):
    rows = []
    for j in range(size):
        row = bytearray(size)
        for i in range(size):
            acc = 0
            for sj in range(ss):
                for si in range(ss):
                    u = ((i + (si + 0.5) / ss) / size) * 2.0 - 1.0
                    v = 1.0 - ((j + (sj + 0.5) / ss) / size) * 2.0   # row 0 is the top (+v)
                    acc += 1 if inside(u, v) else 0
            row[i] = round(255 * acc / (ss * ss))
        rows.append(row)
    return rows


def gobo_dots():
    # Hexagonal grid of round holes: the classic "dots" gobo, reads as a field of points in haze.
    pitch, radius = 0.26, 0.085
    centres = []
    for r in range(-5, 6):
        for c in range(-5, 6):
            x = (c + (0.5 if r % 2 else 0.0)) * pitch
            y = r * pitch * math.sqrt(3) / 2
            if x * x + y * y < 0.93 ** 2:
                centres.append((x, y))
    return lambda u, v: any((u - x) ** 2 + (v - y) ** 2 < radius * radius for x, y in centres)


def gobo_leaves():
    # Breakup: leaf-shaped holes (rotated ellipses) scattered by a fixed seed, like a foliage gobo.
    rng = random.Random(7)
    leaves = []
    # Jittered grid: irregular, but with no large empty patch in the beam.
    cells = [(-1.0 + 0.2 * (i + 0.5), -1.0 + 0.2 * (j + 0.5)) for j in range(10) for i in range(10)]
    for cx, cy in cells:
        x, y = cx + rng.uniform(-0.08, 0.08), cy + rng.uniform(-0.08, 0.08)
        if x * x + y * y > 1.0 or rng.random() < 0.25:
            continue
        a = rng.uniform(0.0, math.pi)
        leaves.append((x, y, math.cos(a), math.sin(a), rng.uniform(0.08, 0.15), rng.uniform(0.035, 0.06)))

    def inside(u, v):
        for x, y, ca, sa, la, lb in leaves:
            du, dv = u - x, v - y
            p, q = du * ca + dv * sa, -du * sa + dv * ca
            if (p / la) ** 2 + (q / lb) ** 2 < 1.0:
                return True
        return False
    return inside


def gobo_spokes():
    # Radial bars: 8 open sectors with a solid hub, so rotation is obvious in the beam.
    def inside(u, v):
        r = math.hypot(u, v)
        if r < 0.16:
            return False
        a = math.atan2(v, u)
        return math.cos(8 * a) > 0.15
    return inside


def deck_texture(size=256):
    # Stage deck planks: 10 boards across the 2 m the texture covers (u = x / 2 m), each with
    # its own tone, a grain and dark joints. sRGB values; their linear mean is about 0.2, the
    # deck albedo a designer wants (dark enough for contrast, light enough to show a gobo).
    rng = random.Random(11)
    boards = 10
    tones = [rng.uniform(0.88, 1.1) for _ in range(boards)]
    offsets = [rng.randrange(size) for _ in range(boards)]
    rows = []
    for j in range(size):
        row = bytearray(size * 3)
        for i in range(size):
            b = i * boards // size
            edge = (i * boards) % size
            joint = edge < 3 or ((j + offsets[b]) % size) < 2   # long joint and a butt joint
            grain = 0.06 * math.sin((j * 0.21 + i * 0.9) + 3.0 * math.sin(j * 0.043 + b))
            base = tones[b] * (1.0 + grain) * (0.35 if joint else 1.0)
            for k, c in enumerate((128, 114, 98)):
                row[3 * i + k] = max(0, min(255, round(c * base)))
        rows.append(row)
    return rows


def srgb_to_linear(c):
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


# --------------------------------------------------------------------------------------------
# Small linear algebra (3-vectors as tuples, 4x4 matrices as row-major lists of rows).


def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def length(a): return math.sqrt(dot(a, a))
def unit(a): return mul(a, 1.0 / length(a))


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def mat_point(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3))


def quat_axis_angle(axis, deg):
    ax = unit(axis)
    h = math.radians(deg) / 2
    return (ax[0] * math.sin(h), ax[1] * math.sin(h), ax[2] * math.sin(h), math.cos(h))


def quat_mul(a, b):  # (x, y, z, w)
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def trs_matrix(t, q, s):
    x, y, z, w = q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def rot_x(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[1, 0, 0], [0, c, -s], [0, s, c]]


def rot_y(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[c, 0, s], [0, 1, 0], [-s, 0, c]]


def rot_z(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def m3(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def m3v(a, v):
    return tuple(a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2] for i in range(3))


def m3t(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


# --------------------------------------------------------------------------------------------
# Unit meshes (positions, normals, uvs, triangle indices), counter-clockwise seen from outside.


def box_mesh(uv_scale=None):
    # Unit cube centred on the origin. Faces get their own vertices (flat normals). uv_scale
    # (sx, sy, sz) maps uv in metres / 2 for a textured slab; None gives 0..1 per face.
    pos, nrm, uv, idx = [], [], [], []
    faces = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]
    for n, u_ax, v_ax in faces:
        base = len(pos)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = tuple(0.5 * n[k] + 0.5 * su * u_ax[k] + 0.5 * sv * v_ax[k] for k in range(3))
            pos.append(p)
            nrm.append(n)
            if uv_scale is None:
                uv.append((0.5 + 0.5 * su, 0.5 - 0.5 * sv))
            else:
                world = tuple(p[k] * uv_scale[k] for k in range(3))
                uv.append((dot(world, u_ax) / 2.0, -dot(world, v_ax) / 2.0))
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uv, idx


def cylinder_mesh(segments=24):
    # Radius 1, y from 0 to 1, with caps.
    pos, nrm, uv, idx = [], [], [], []
    for i in range(segments + 1):
        a = 2 * math.pi * i / segments
        c, s = math.cos(a), math.sin(a)
        for y in (0.0, 1.0):
            pos.append((c, y, -s))
            nrm.append((c, 0.0, -s))
            uv.append((i / segments, 1.0 - y))
    for i in range(segments):
        a, b = 2 * i, 2 * i + 2
        idx += [a, b, b + 1, a, b + 1, a + 1]
    for y, ny in ((0.0, -1.0), (1.0, 1.0)):
        centre = len(pos)
        pos.append((0.0, y, 0.0))
        nrm.append((0.0, ny, 0.0))
        uv.append((0.5, 0.5))
        for i in range(segments + 1):
            a = 2 * math.pi * i / segments
            pos.append((math.cos(a), y, -math.sin(a)))
            nrm.append((0.0, ny, 0.0))
            uv.append((0.5 + 0.5 * math.cos(a), 0.5 + 0.5 * math.sin(a)))
        for i in range(segments):
            p, q = centre + 1 + i, centre + 2 + i
            idx += [centre, p, q] if ny > 0 else [centre, q, p]
    return pos, nrm, uv, idx


def sphere_mesh(stacks=16, slices=32):
    # Radius 1 around the origin.
    pos, nrm, uv, idx = [], [], [], []
    for j in range(stacks + 1):
        th = math.pi * j / stacks
        for i in range(slices + 1):
            ph = 2 * math.pi * i / slices
            n = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            pos.append(n)
            nrm.append(n)
            uv.append((i / slices, j / stacks))
    for j in range(stacks):
        for i in range(slices):
            a = j * (slices + 1) + i
            b = a + slices + 1
            if j > 0:
                idx += [a, b, a + 1]
            if j < stacks - 1:
                idx += [a + 1, b, b + 1]
    return pos, nrm, uv, idx


# --------------------------------------------------------------------------------------------
# glTF writer: one .bin, a bufferView per accessor (tightly packed, 4-byte aligned).


class Gltf:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "haze tools/make_demo_venue.py"},
                    "scene": 0, "scenes": [{"name": "Theatre", "nodes": []}], "nodes": [],
                    "meshes": [], "materials": [], "accessors": [], "bufferViews": [],
                    "buffers": [], "images": [], "samplers": [], "textures": []}
        self.mesh_data = []        # per mesh: (positions, indices), for the ray-cast checks
        self.node_names = set()

    def _view(self, data, target):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin),
                                        "byteLength": len(data), "target": target})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, kind, component, target, with_bounds=False):
        if kind == "SCALAR":
            fmt = {5123: "H", 5125: "I"}[component]
            data = struct.pack("<%d%s" % (len(values), fmt), *values)
        else:
            flat = [c for v in values for c in v]
            data = struct.pack("<%df" % len(flat), *flat)
        acc = {"bufferView": self._view(data, target), "componentType": component,
               "count": len(values), "type": kind}
        if with_bounds:
            n = len(values[0])
            acc["min"] = [min(v[k] for v in values) for k in range(n)]
            acc["max"] = [max(v[k] for v in values) for k in range(n)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def material(self, name, base, texture=None, emissive=None, strength=None):
        m = {"name": name,
             "pbrMetallicRoughness": {"baseColorFactor": [base[0], base[1], base[2], 1.0],
                                      "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if texture is not None:
            m["pbrMetallicRoughness"]["baseColorTexture"] = {"index": texture}
        if emissive is not None:
            m["emissiveFactor"] = list(emissive)
        if strength is not None:
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": strength}}
            self.doc.setdefault("extensionsUsed", [])
            if "KHR_materials_emissive_strength" not in self.doc["extensionsUsed"]:
                self.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def texture(self, uri):
        self.doc["images"].append({"uri": uri})
        if not self.doc["samplers"]:
            # Trilinear, repeating: the deck UVs run over several texture tiles.
            self.doc["samplers"].append({"magFilter": 9729, "minFilter": 9987,
                                         "wrapS": 10497, "wrapT": 10497})
        self.doc["textures"].append({"sampler": 0, "source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def mesh(self, name, geometry, material, index_type=5123):
        pos, nrm, uv, idx = geometry
        assert max(idx) < len(pos), "index past the vertices"
        assert index_type == 5125 or len(pos) <= 65535, "too many vertices for uint16 indices"
        prim = {"attributes": {"POSITION": self._accessor(pos, "VEC3", 5126, 34962, True),
                               "NORMAL": self._accessor(nrm, "VEC3", 5126, 34962),
                               "TEXCOORD_0": self._accessor(uv, "VEC2", 5126, 34962)},
                "indices": self._accessor(idx, "SCALAR", index_type, 34963),
                "material": material, "mode": 4}
        self.doc["meshes"].append({"name": name, "primitives": [prim]})
        self.mesh_data.append((pos, idx))
        return len(self.doc["meshes"]) - 1

    def node(self, name, mesh=None, t=None, q=None, s=None, children=(), parent=None):
        assert name not in self.node_names, "node names are unique: " + name
        self.node_names.add(name)
        n = {"name": name}
        if mesh is not None:
            n["mesh"] = mesh
        if t is not None:
            n["translation"] = [round(c, 6) for c in t]
        if q is not None:
            n["rotation"] = [round(c, 9) for c in q]
        if s is not None:
            n["scale"] = [round(c, 6) for c in s]
        self.doc["nodes"].append(n)
        index = len(self.doc["nodes"]) - 1
        if parent is None:
            self.doc["scenes"][0]["nodes"].append(index)
        else:
            self.doc["nodes"][parent].setdefault("children", []).append(index)
        return index

    def finish(self, bin_name):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc["buffers"].append({"uri": bin_name, "byteLength": len(self.bin)})
        return self.doc, bytes(self.bin)


# --------------------------------------------------------------------------------------------
# The venue. House floor at y = 0, deck top at y = 1, audience at +z looking towards -z.

DECK_TOP_Y = 1.0
TRUSS_CENTRE = (0.0, 8.15, -3.0)       # 30 cm box truss, bottom chords' underside at y = 8.0
TRUSS_HALF = 0.125                     # chord centres at +-12.5 cm from the truss axis
CHORD = 0.05
TRUSS_LENGTH = 8.0
TRUSS_BOTTOM_Y = TRUSS_CENTRE[1] - TRUSS_HALF - CHORD / 2   # 8.0: where the clamps hang
FRONT_CHORD_Z = TRUSS_CENTRE[2] + TRUSS_HALF                # -2.875 (downstage chord)
BACK_CHORD_Z = TRUSS_CENTRE[2] - TRUSS_HALF                 # -3.125 (upstage chord)

COLUMN = {"x": -2.5, "z": -4.5, "radius": 0.25, "height": 4.0}
SPHERE = {"centre": (0.9, DECK_TOP_Y + 0.55, -1.8), "radius": 0.55}
STAIR = {"origin": (2.6, DECK_TOP_Y, -3.6), "yaw": -20.0}
TREE = (3.9, DECK_TOP_Y, -1.0)
LAMP = (-3.7, DECK_TOP_Y, -1.3)   # a practical standard lamp, downstage left
FRAME = {"centre": (0.0, 4.6, -6.3), "size": 2.4, "yaw": 10.0}
CYC_Z = -7.15


def build_venue():
    g = Gltf()
    tex = g.texture("deck_planks.png")
    mat = {
        "deck": g.material("deck_wood", (1.0, 1.0, 1.0), texture=tex),
        "black": g.material("masking_black", (0.03, 0.03, 0.03)),
        "wall": g.material("house_wall", (0.35, 0.34, 0.32)),
        "backwall": g.material("stage_back_wall", (0.3, 0.3, 0.3)),
        "cyc": g.material("cyclorama", (0.7, 0.7, 0.7)),
        "carpet": g.material("house_carpet", (0.1, 0.06, 0.05)),
        "seat": g.material("seat_velvet", (0.16, 0.03, 0.03)),
        "prosc": g.material("proscenium", (0.22, 0.06, 0.05)),
        "ceiling": g.material("house_ceiling", (0.12, 0.12, 0.12)),
        "truss": g.material("truss_aluminium", (0.6, 0.6, 0.6)),
        "set": g.material("set_paint", (0.45, 0.44, 0.42)),
        "frame": g.material("frame_paint", (0.3, 0.3, 0.32)),
        "bark": g.material("tree_bark", (0.12, 0.08, 0.05)),
        "leaf": g.material("tree_leaves", (0.08, 0.2, 0.06)),
        "sphere": g.material("sphere_white", (0.6, 0.6, 0.6)),
        # Emissive: cd/m^2 = emissiveFactor * emissiveStrength (haze's venue loader).
        "exit": g.material("exit_sign", (0.05, 0.3, 0.05), emissive=(0.1, 1.0, 0.25), strength=40.0),
        "lamp": g.material("practical_shade", (0.8, 0.7, 0.55), emissive=(1.0, 0.75, 0.45), strength=60.0),
    }
    # One unit-box mesh per material, reused by many nodes (scale gives the size).
    box = {k: g.mesh("box_" + k, box_mesh(), m) for k, m in mat.items() if k != "deck"}
    cyl = {k: g.mesh("cylinder_" + k, cylinder_mesh(), mat[k]) for k in ("set", "lamp", "black")}
    sphere = g.mesh("sphere", sphere_mesh(), mat["sphere"], index_type=5125)   # uint32 indices
    deck_size = (10.0, 0.02, 7.5)
    deck_top = g.mesh("deck_top", box_mesh(uv_scale=deck_size), mat["deck"])

    def boxn(name, material, lo, hi, parent=None):
        centre = mul(add(lo, hi), 0.5)
        size = sub(hi, lo)
        return g.node(name, box[material], t=centre, s=size, parent=parent)

    # House: floor, seat rows with a centre aisle, walls, ceiling, exit signs.
    house = g.node("House")
    boxn("house_floor", "carpet", (-8, -0.1, 0), (8, 0, 15), house)
    for r in range(8):
        z0 = 3.0 + 1.1 * r
        for side, (x0, x1) in (("L", (-6.5, -0.7)), ("R", (0.7, 6.5))):
            boxn("seats_row%d_%s" % (r + 1, side), "seat", (x0, 0, z0), (x1, 0.85, z0 + 0.55), house)
    boxn("house_wall_L", "wall", (-8.3, 0, -7.8), (-8, 11, 15), house)
    boxn("house_wall_R", "wall", (8, 0, -7.8), (8.3, 11, 15), house)
    boxn("house_back_wall", "wall", (-8, 0, 15), (8, 11, 15.3), house)
    boxn("house_ceiling", "ceiling", (-8, 11, -0.4), (8, 11.2, 15), house)
    boxn("exit_sign_L", "exit", (-7.99, 3.0, 1.2), (-7.95, 3.25, 1.8), house)
    boxn("exit_sign_R", "exit", (7.95, 3.0, 1.2), (7.99, 3.25, 1.8), house)
    boxn("exit_sign_back", "exit", (-0.3, 3.0, 14.95), (0.3, 3.25, 14.99), house)

    # Stage: black deck body, planked top slab, back wall, cyc, fly-tower roof, masking legs.
    stage = g.node("Stage")
    boxn("deck_body", "black", (-5, 0, -7.5), (5, DECK_TOP_Y - deck_size[1], 0), stage)
    g.node("deck_top", deck_top, t=(0, DECK_TOP_Y - deck_size[1] / 2, -3.75), s=deck_size, parent=stage)
    boxn("stage_floor_wings_L", "black", (-8, 0, -7.5), (-5, DECK_TOP_Y, -0.8), stage)
    boxn("stage_floor_wings_R", "black", (5, 0, -7.5), (8, DECK_TOP_Y, -0.8), stage)
    boxn("stage_back_wall", "backwall", (-8, 0, -7.8), (8, 12.2, -7.5), stage)
    boxn("cyclorama", "cyc", (-5.5, DECK_TOP_Y, CYC_Z - 0.05), (5.5, 9.5, CYC_Z), stage)
    boxn("fly_tower_roof", "black", (-8, 12.0, -7.8), (8, 12.2, -0.4), stage)
    for i, z in enumerate((-2.0, -5.0)):
        boxn("leg_L%d" % (i + 1), "black", (-6.0, DECK_TOP_Y, z - 0.03), (-4.8, 9.0, z + 0.03), stage)
        boxn("leg_R%d" % (i + 1), "black", (4.8, DECK_TOP_Y, z - 0.03), (6.0, 9.0, z + 0.03), stage)

    # Proscenium arch: two legs and a header, in front of the first truss.
    prosc = g.node("Proscenium", t=(0, 0, -0.6))
    boxn("prosc_leg_L", "prosc", (-8, 0, -0.2), (-4.6, 11, 0.2), prosc)
    boxn("prosc_leg_R", "prosc", (4.6, 0, -0.2), (8, 11, 0.2), prosc)
    boxn("prosc_header", "prosc", (-4.6, 9.2, -0.2), (4.6, 11, 0.2), prosc)

    # Box truss: 4 chords, diagonal lacing on each face (a node per tube: rotations), two pickups.
    truss = g.node("Truss", t=TRUSS_CENTRE)
    h = TRUSS_HALF
    for cy in (-h, h):
        for cz in (-h, h):
            g.node("chord_%s_%s" % ("top" if cy > 0 else "bottom", "front" if cz > 0 else "back"),
                   box["truss"], t=(0, cy, cz), s=(TRUSS_LENGTH, CHORD, CHORD), parent=truss)
    bay = 0.5
    bays = int(TRUSS_LENGTH / bay)
    diag = math.hypot(bay, 2 * h)
    ang = math.degrees(math.atan2(2 * h, bay))
    for b in range(bays):
        xc = -TRUSS_LENGTH / 2 + (b + 0.5) * bay
        sgn = 1 if b % 2 == 0 else -1
        for cz, face in ((h, "front"), (-h, "back")):     # vertical faces: turn about z
            g.node("lacing_%s_%02d" % (face, b), box["truss"], t=(xc, 0, cz),
                   q=quat_axis_angle((0, 0, 1), sgn * ang), s=(diag, 0.02, 0.02), parent=truss)
        for cy, face in ((h, "top"), (-h, "bottom")):     # horizontal faces: turn about y
            g.node("lacing_%s_%02d" % (face, b), box["truss"], t=(xc, cy, 0),
                   q=quat_axis_angle((0, 1, 0), sgn * ang), s=(diag, 0.02, 0.02), parent=truss)
    for x in (-3.5, 3.5):
        g.node("truss_pickup_%s" % ("L" if x < 0 else "R"), box["black"],
               t=(x, (12.0 - TRUSS_CENTRE[1] + h) / 2 + 0.0, 0),
               s=(0.02, 12.0 - TRUSS_CENTRE[1] - h, 0.02), parent=truss)

    # Set pieces that cut shadows through the beams.
    setp = g.node("Set")
    col = g.node("column", t=(COLUMN["x"], DECK_TOP_Y, COLUMN["z"]), parent=setp)
    # The shaft ends 5 cm inside the capital, so no two faces share the capital's top plane.
    g.node("column_shaft", cyl["set"], s=(COLUMN["radius"], COLUMN["height"] - 0.05, COLUMN["radius"]), parent=col)
    g.node("column_plinth", box["set"], t=(0, 0.1, 0), s=(0.7, 0.2, 0.7), parent=col)
    g.node("column_capital", box["set"], t=(0, COLUMN["height"] - 0.1, 0), s=(0.7, 0.2, 0.7), parent=col)

    stair = g.node("stair_unit", t=STAIR["origin"], q=quat_axis_angle((0, 1, 0), STAIR["yaw"]), parent=setp)
    for k in range(4):   # rises upstage (-z in its own frame), 25 cm risers, 40 cm goings
        top = 0.25 * (k + 1)
        g.node("stair_step_%d" % (k + 1), box["set"], t=(0, top / 2, 0.8 - 0.4 * k - 0.2),
               s=(2.0, top, 0.4), parent=stair)

    fr = g.node("hanging_frame", t=FRAME["centre"], q=quat_axis_angle((0, 1, 0), FRAME["yaw"]), parent=setp)
    half, bar, thick = FRAME["size"] / 2, 0.12, 0.08
    for name, t, s in (("top", (0, half - bar / 2, 0), (2 * half, bar, thick)),
                       ("bottom", (0, -half + bar / 2, 0), (2 * half, bar, thick)),
                       ("left", (-half + bar / 2, 0, 0), (bar, 2 * half, thick)),
                       ("right", (half - bar / 2, 0, 0), (bar, 2 * half, thick))):
        g.node("frame_" + name, box["frame"], t=t, s=s, parent=fr)
    for k, off in enumerate((-half / 3, half / 3)):   # mullions: 3 x 3 openings
        g.node("frame_mullion_v%d" % (k + 1), box["frame"], t=(off, 0, 0), s=(0.06, 2 * half, thick), parent=fr)
        g.node("frame_mullion_h%d" % (k + 1), box["frame"], t=(0, off, 0), s=(2 * half, 0.06, thick), parent=fr)
    cable = 12.0 - FRAME["centre"][1] - half
    for k, x in enumerate((-0.9, 0.9)):
        g.node("frame_cable_%d" % (k + 1), box["black"], t=(x, half + cable / 2, 0), s=(0.01, cable, 0.01), parent=fr)

    tree = g.node("tree", t=TREE, s=(0.8, 0.8, 0.8), parent=setp)   # scaled as a whole
    g.node("tree_trunk", box["bark"], t=(0, 1.3, 0), s=(0.2, 2.6, 0.2), parent=tree)
    for k, (yaw, tilt, y) in enumerate(((0, 35, 1.9), (120, 40, 2.2), (240, 30, 2.5), (60, -35, 2.0))):
        limb = g.node("tree_limb_%d" % (k + 1), t=(0, y, 0),
                      q=quat_mul(quat_axis_angle((0, 1, 0), yaw), quat_axis_angle((0, 0, 1), tilt)), parent=tree)
        g.node("tree_branch_%d" % (k + 1), box["bark"], t=(0, 0.45, 0), s=(0.09, 0.9, 0.09), parent=limb)
        g.node("tree_leaves_%d" % (k + 1), box["leaf"], t=(0, 1.0, 0), s=(0.5, 0.35, 0.5), parent=limb)
    g.node("tree_crown", box["leaf"], t=(0, 2.8, 0), s=(0.7, 0.5, 0.7), parent=tree)

    g.node("sphere", sphere, t=SPHERE["centre"], s=(SPHERE["radius"],) * 3, parent=setp)

    lamp = g.node("practical_lamp", t=LAMP, parent=setp)
    g.node("lamp_base", cyl["black"], s=(0.18, 0.03, 0.18), parent=lamp)
    g.node("lamp_pole", cyl["black"], s=(0.015, 1.35, 0.015), parent=lamp)
    g.node("lamp_shade", cyl["lamp"], t=(0, 1.3, 0), s=(0.2, 0.3, 0.2), parent=lamp)
    return g


# --------------------------------------------------------------------------------------------
# World-space triangles (node transforms applied), for the checks below.


def world_triangles(doc, mesh_data):
    tris = []

    def walk(index, parent_m):
        n = doc["nodes"][index]
        m = mat_mul(parent_m, trs_matrix(n.get("translation", (0, 0, 0)), n.get("rotation", (0, 0, 0, 1)),
                                         n.get("scale", (1, 1, 1))))
        if "mesh" in n:
            pos, idx = mesh_data[n["mesh"]]
            wp = [mat_point(m, p) for p in pos]
            for k in range(0, len(idx), 3):
                tris.append((wp[idx[k]], wp[idx[k + 1]], wp[idx[k + 2]], n["name"]))
        for c in n.get("children", []):
            walk(c, m)
    ident = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    for r in doc["scenes"][doc["scene"]]["nodes"]:
        walk(r, ident)
    return tris


def raycast(tris, origin, direction, t_max=200.0):
    # Moller-Trumbore; returns (distance, node name) of the first hit, or (None, None).
    best, name = t_max, None
    for a, b, c, nm in tris:
        e1, e2 = sub(b, a), sub(c, a)
        p = cross(direction, e2)
        det = dot(e1, p)
        if abs(det) < 1e-12:
            continue
        inv = 1.0 / det
        s = sub(origin, a)
        u = dot(s, p) * inv
        if u < 0 or u > 1:
            continue
        q = cross(s, e1)
        v = dot(direction, q) * inv
        if v < 0 or u + v > 1:
            continue
        t = dot(e2, q) * inv
        if 1e-6 < t < best:
            best, name = t, nm
    return (best, name) if name else (None, None)


def verify_gltf(gltf_path):
    # Re-read the written files as a reader would and check what a validator checks.
    with open(gltf_path) as f:
        doc = json.load(f)
    base = os.path.dirname(gltf_path)
    buf = doc["buffers"][0]
    with open(os.path.join(base, buf["uri"]), "rb") as f:
        data = f.read()
    assert len(data) == buf["byteLength"], "buffer byteLength differs from the .bin's size"
    sizes = {5126: (4, "f"), 5123: (2, "H"), 5125: (4, "I")}
    ncomp = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}

    def read(ai):
        acc = doc["accessors"][ai]
        view = doc["bufferViews"][acc["bufferView"]]
        size, fmt = sizes[acc["componentType"]]
        n = ncomp[acc["type"]]
        off = view["byteOffset"] + acc.get("byteOffset", 0)
        assert off % size == 0, "accessor %d misaligned" % ai
        assert acc.get("byteOffset", 0) + acc["count"] * n * size <= view["byteLength"], "accessor %d overruns its view" % ai
        assert view["byteOffset"] + view["byteLength"] <= len(data), "view overruns the buffer"
        vals = struct.unpack_from("<%d%s" % (acc["count"] * n, fmt), data, off)
        return [vals[i:i + n] for i in range(0, len(vals), n)] if n > 1 else list(vals)

    for mi, mesh in enumerate(doc["meshes"]):
        for prim in mesh["primitives"]:
            a = prim["attributes"]
            pos, nrm, uv = read(a["POSITION"]), read(a["NORMAL"]), read(a["TEXCOORD_0"])
            idx = read(prim["indices"])
            acc = doc["accessors"][a["POSITION"]]
            assert len(pos) == len(nrm) == len(uv) == acc["count"], mesh["name"]
            for k in range(3):
                lo, hi = min(p[k] for p in pos), max(p[k] for p in pos)
                assert abs(lo - acc["min"][k]) < 1e-6 and abs(hi - acc["max"][k]) < 1e-6, "bounds of " + mesh["name"]
            assert all(abs(length(n) - 1.0) < 1e-5 for n in nrm), "normals of %s not unit" % mesh["name"]
            assert len(idx) % 3 == 0 and max(idx) < len(pos), "indices of " + mesh["name"]
            assert prim["material"] < len(doc["materials"])
    for img in doc["images"]:
        w, h = read_png_size(os.path.join(base, img["uri"]))
        assert w > 0 and h > 0
    for n in doc["nodes"]:
        if "rotation" in n:
            assert abs(length(n["rotation"][:3] + [0]) ** 2 + n["rotation"][3] ** 2 - 1) < 1e-6, "quaternion not unit"
    return doc


# --------------------------------------------------------------------------------------------
# Fixture profiles (docs/show-format.md, native JSON). Parametric photometry: no external data.

GOBOS = [("Dots", "dots.png", gobo_dots), ("Leaves", "leaves.png", gobo_leaves),
         ("Spokes", "spokes.png", gobo_spokes)]

PROFILES = {
    "spot": ("profile-spot.json", {
        "format": "haze-fixture", "version": 1,
        "manufacturer": "haze demo",
        "name": "Profile Spot 600",
        "photometry": {"beam_angle": 14.0, "field_angle": 20.0, "peak_candela": 60000.0},
        "lens_offset": [0.0, -0.25, 0.0],
        "field_angle": 20.0,
        "zoom": {"min": 8.0, "max": 40.0},
        "pan": {"min": -270.0, "max": 270.0},
        "tilt": {"min": -135.0, "max": 135.0},
        "color": {"mixing": "cmy"},
        "gobo_wheels": [{"name": "Gobo 1", "slots": [{"name": "Open"}] + [
            {"name": n, "image": "../gobos/" + f} for n, f, _ in GOBOS]}],
        "modes": [{"name": "Standard", "channels": [
            "Dimmer", "Pan", "Pan fine", "Tilt", "Tilt fine", "Cyan", "Magenta", "Yellow",
            "Gobo 1", "Gobo 1 rotation", "Zoom", "Iris"]}],
    }),
    "wash": ("led-wash.json", {
        "format": "haze-fixture", "version": 1,
        "manufacturer": "haze demo",
        "name": "LED Wash 19",
        "photometry": {"beam_angle": 20.0, "field_angle": 35.0, "peak_candela": 20000.0},
        "lens_offset": [0.0, -0.2, 0.0],
        "field_angle": 35.0,
        "zoom": {"min": 10.0, "max": 60.0},
        "pan": {"min": -270.0, "max": 270.0},
        "tilt": {"min": -135.0, "max": 135.0},
        "color": {"mixing": "rgb"},
        "modes": [{"name": "Standard", "channels": [
            "Dimmer", "Pan", "Pan fine", "Tilt", "Tilt fine", "Red", "Green", "Blue", "Zoom"]}],
    }),
    "beam": ("beam.json", {
        "format": "haze-fixture", "version": 1,
        "manufacturer": "haze demo",
        "name": "Beam 230",
        "photometry": {"beam_angle": 4.0, "field_angle": 6.0, "peak_candela": 800000.0},
        "lens_offset": [0.0, -0.2, 0.0],
        "field_angle": 6.0,
        "zoom": {"min": 6.0, "max": 6.0},
        "pan": {"min": -270.0, "max": 270.0},
        "tilt": {"min": -125.0, "max": 125.0},
        "color": {"mixing": "cmy"},
        "modes": [{"name": "Standard", "channels": [
            "Dimmer", "Pan", "Pan fine", "Tilt", "Tilt fine", "Cyan", "Magenta", "Yellow"]}],
    }),
}

# --------------------------------------------------------------------------------------------
# The rig: 4 spots on the truss's downstage chord, 4 washes on its upstage chord, 4 beams
# standing on the deck in front of the cyc (rotation [180, 0, 0]: local -Y points up).

FIXTURES = []
for k, x in enumerate((-3.0, -1.0, 1.0, 3.0)):
    FIXTURES.append({"id": 101 + k, "name": "Spot %d" % (k + 1), "profile": "spot",
                     "position": (x, TRUSS_BOTTOM_Y, FRONT_CHORD_Z), "rotation": (0, 0, 0)})
for k, x in enumerate((-3.5, -1.5, 1.5, 3.5)):
    FIXTURES.append({"id": 201 + k, "name": "Wash %d" % (k + 1), "profile": "wash",
                     "position": (x, TRUSS_BOTTOM_Y, BACK_CHORD_Z), "rotation": (0, 0, 0)})
for k, x in enumerate((-3.6, -1.0, 1.0, 3.6)):
    FIXTURES.append({"id": 301 + k, "name": "Floor beam %d" % (k + 1), "profile": "beam",
                     "position": (x, DECK_TOP_Y, -6.6), "rotation": (180, 0, 0)})
FIX = {f["id"]: f for f in FIXTURES}
FIRST_ADDRESS = {"spot": 1, "wash": 101, "beam": 201}   # each type starts at a round address


def mounting(rot):
    return m3(m3(rot_z(rot[2]), rot_y(rot[1])), rot_x(rot[0]))


def beam_axis(rot, pan, tilt):
    m = m3(m3(mounting(rot), rot_y(pan)), rot_x(tilt))
    return m3v(m, (0, -1, 0)), m


def aim(fid, target):
    # Pan/tilt that put the beam axis through target: in the mounting frame the axis is
    # (-sin t sin p, -cos t, -sin t cos p); of the two solutions (p, t) and (p + 180, -t) and
    # their 360-degree turns, take the one within range with the smallest |pan|, then |tilt|.
    f = FIX[fid]
    prof = PROFILES[f["profile"]][1]
    d = unit(sub(target, f["position"]))  # the lens lies on this line: lens = pos + 0.2-0.25 * z_b
    local = m3v(m3t(mounting(f["rotation"])), d)
    t = math.degrees(math.acos(max(-1.0, min(1.0, -local[1]))))
    p = math.degrees(math.atan2(-local[0], -local[2])) if abs(t) > 1e-6 else 0.0
    cands = []
    for pp, tt in ((p, t), (p + 180.0, -t), (p - 180.0, -t)):
        for turn in (-360.0, 0.0, 360.0):
            q = pp + turn
            if prof["pan"]["min"] <= q <= prof["pan"]["max"] and prof["tilt"]["min"] <= tt <= prof["tilt"]["max"]:
                cands.append((abs(q), abs(tt), q, tt))
    assert cands, "fixture %d cannot reach %s" % (fid, target)
    _, _, q, tt = min(cands)
    return round(q, 1), round(tt, 1)


# Named targets (world metres).
T = {
    "column_top": (COLUMN["x"], DECK_TOP_Y + COLUMN["height"], COLUMN["z"]),
    "column_mid": (COLUMN["x"], DECK_TOP_Y + 2.2, COLUMN["z"]),
    "sphere_top": add(SPHERE["centre"], (0, SPHERE["radius"], 0)),
    "stair_top": add(STAIR["origin"], m3v(rot_y(STAIR["yaw"]), (0.0, 1.0, -0.6))),  # top tread's centre
    "frame_centre": FRAME["centre"],
    "tree_crown": add(TREE, (0.0, 0.8 * 2.8, 0.0)),
    "lamp": add(LAMP, (0.0, 1.45, 0.0)),
    "dsc": (0.0, DECK_TOP_Y, -1.2),
}


def rgb(r, g, b):
    return [r, g, b]


def build_cues():
    # Each cue's values; pan/tilt from aim(). Beams not in use stay at pan 0, tilt 0 (straight up).
    targets = {}   # cue number -> fixture id -> the point its beam axis is meant to pass through

    def at(fid, name_or_point):
        p = T[name_or_point] if isinstance(name_or_point, str) else name_or_point
        pan, tilt = aim(fid, p)
        targets.setdefault(str(len(cues)), {})[fid] = p
        return {"pan": pan, "tilt": tilt}

    warm = rgb(1.0, 0.78, 0.52)
    cues = []

    # 1 Preset: warm wash over the four stage areas, spots in open white on the set pieces.
    v = {}
    for fid, tgt in ((201, (-2.6, DECK_TOP_Y, -1.6)), (202, (-1.3, DECK_TOP_Y, -5.0)),
                     (203, (1.3, DECK_TOP_Y, -5.0)), (204, (2.6, DECK_TOP_Y, -1.6))):
        v[fid] = {"intensity": 0.8, **at(fid, tgt), "color": warm, "zoom": 45.0}
    for fid, tgt in ((101, "column_mid"), (102, "sphere_top"), (103, "column_top"), (104, "stair_top")):
        v[fid] = {"intensity": 0.7, **at(fid, tgt), "color": rgb(1.0, 0.96, 0.88), "zoom": 14.0,
                  "gobo": "Open", "gobo_rotation": 0.0, "iris": 1.0}
    for fid in (301, 302, 303, 304):
        v[fid] = {"intensity": 0.0, "pan": 0.0, "tilt": 0.0, "color": rgb(1.0, 1.0, 1.0)}
    cues.append({"number": "1", "label": "Preset", "fade": 5.0, "delay": 0.0, "follow": None, "values": v})

    # 2 Gobos: the spots cross in pairs through the haze with breakup gobos, turned; wash in deep blue.
    v = {}
    for fid, tgt, gobo, rot in ((101, (2.2, DECK_TOP_Y, -1.4), "Leaves", 30.0),
                                (104, (-2.2, DECK_TOP_Y, -1.4), "Leaves", -30.0),
                                (102, (1.8, DECK_TOP_Y, -5.4), "Dots", 0.0),
                                (103, (-1.8, DECK_TOP_Y, -5.4), "Dots", 45.0)):
        v[fid] = {"intensity": 1.0, **at(fid, tgt), "color": rgb(0.62, 0.78, 1.0), "zoom": 22.0,
                  "gobo": gobo, "gobo_rotation": rot}
    for fid in (201, 202, 203, 204):
        v[fid] = {"intensity": 0.35, "color": rgb(0.08, 0.2, 1.0), "zoom": 55.0}
    cues.append({"number": "2", "label": "Gobos", "fade": 6.0, "delay": 0.0, "follow": None, "values": v})

    # 3 Colour crossfade (2 s delay): saturated colours; spots 1 and 4 cross at the column, so
    # its shadow runs up the beams; spots 2 and 3 cross through the hanging frame onto the cyc.
    v = {}
    for fid, tgt, col in ((101, "column_mid", rgb(1.0, 0.05, 0.55)), (104, "column_mid", rgb(0.05, 0.85, 1.0)),
                          (102, "frame_centre", rgb(1.0, 0.45, 0.0)), (103, "frame_centre", rgb(0.55, 0.0, 1.0))):
        v[fid] = {"intensity": 1.0, **at(fid, tgt), "color": col, "zoom": 12.0, "gobo": "Open"}
    for fid, tgt, col in ((201, (-3.5, 4.0, CYC_Z), rgb(1.0, 0.0, 0.25)), (202, (-1.2, 2.5, CYC_Z), rgb(0.0, 0.1, 1.0)),
                          (203, (1.2, 2.5, CYC_Z), rgb(0.0, 0.1, 1.0)), (204, (3.5, 4.0, CYC_Z), rgb(1.0, 0.0, 0.25))):
        v[fid] = {"intensity": 0.9, **at(fid, tgt), "color": col, "zoom": 30.0}
    cues.append({"number": "3", "label": "Colour crossfade", "fade": 8.0, "delay": 2.0, "follow": None, "values": v})

    # 4 Finale: everything at full, narrow; spots fan out over the audience, the floor beams
    # fan up through the proscenium, the washes fan across the cyc. Follows on into 4.5.
    v = {}
    for fid, tgt in ((101, (-6.2, 0.85, 6.1)), (102, (-2.1, 0.85, 7.6)), (103, (2.1, 0.85, 7.6)), (104, (6.2, 0.85, 6.1))):
        v[fid] = {"intensity": 1.0, **at(fid, tgt), "color": rgb(1.0, 1.0, 1.0), "zoom": 8.0, "gobo": "Open"}
    for fid, tgt in ((201, (-5.0, 2.0, CYC_Z)), (202, (-1.7, 6.0, CYC_Z)), (203, (1.7, 6.0, CYC_Z)), (204, (5.0, 2.0, CYC_Z))):
        v[fid] = {"intensity": 1.0, **at(fid, tgt), "color": rgb(0.1, 0.25, 1.0), "zoom": 10.0}
    for fid, tgt in ((301, (-5.5, 11.0, 9.0)), (302, (-2.0, 11.0, 11.0)), (303, (2.0, 11.0, 11.0)), (304, (5.5, 11.0, 9.0))):
        v[fid] = {"intensity": 1.0, **at(fid, tgt), "color": rgb(1.0, 1.0, 1.0)}
    cues.append({"number": "4", "label": "Finale", "fade": 3.0, "delay": 0.0, "follow": 2.0, "values": v})

    # 4.5 Finale sweep: the fans cross over (mirror targets) and the beams turn amber.
    v = {}
    for fid, tgt in ((101, (4.2, 0.85, 7.6)), (102, (1.0, 0.85, 9.8)), (103, (-1.0, 0.85, 9.8)), (104, (-4.2, 0.85, 7.6))):
        v[fid] = at(fid, tgt)
    for fid, tgt in ((301, (-1.0, 11.0, 6.0)), (302, (-5.5, 11.0, 10.0)), (303, (5.5, 11.0, 10.0)), (304, (1.0, 11.0, 6.0))):
        v[fid] = {**at(fid, tgt), "color": rgb(1.0, 0.55, 0.1)}
    cues.append({"number": "4.5", "label": "Finale sweep", "fade": 5.0, "delay": 0.0, "follow": None, "values": v,
                 # The beams circle (a ballyhoo) round their new aim, evenly spread round the cycle.
                 "effects": [{"shape": "circle", "group": "Beams", "rate": 0.2, "size": 4.0, "spread": 360.0}]})

    # 5 Bows: beams and spots out, the washes open and warm over the whole deck.
    v = {}
    for fid in (101, 102, 103, 104, 301, 302, 303, 304):
        v[fid] = {"intensity": 0.0}
    for fid, tgt in ((201, (-2.6, DECK_TOP_Y, -1.2)), (202, (-1.0, DECK_TOP_Y, -2.5)),
                     (203, (1.0, DECK_TOP_Y, -2.5)), (204, (2.6, DECK_TOP_Y, -1.2))):
        v[fid] = {"intensity": 1.0, **at(fid, tgt), "color": warm, "zoom": 60.0}
    cues.append({"number": "5", "label": "Bows", "fade": 4.0, "delay": 0.0, "follow": None, "values": v})
    # Re-key the targets from the cue's index to its number.
    return cues, {cues[int(k)]["number"]: v for k, v in targets.items()}


# --------------------------------------------------------------------------------------------
# Groups and palettes (show format version 2). The cues above hold every value explicitly;
# factor_palettes moves the values named here into palettes and leaves a reference in the cue, so
# each cue plays exactly as before (tests/cli/show_migration.sh compares every cue's state with
# the version-1 demo kept in tests/data/shows/demo-v1.haze.json).

SPOTS, WASHES, BEAMS = [101, 102, 103, 104], [201, 202, 203, 204], [301, 302, 303, 304]
GROUPS = [("Spots", SPOTS), ("Washes", WASHES), ("Beams", BEAMS)]
KIND_ATTRS = {"position": ("pan", "tilt"), "color": ("color",), "beam": ("zoom", "gobo", "gobo_rotation", "iris")}
PALETTE_USES = [  # name, kind, [(cue number, fixtures)]
    ("Warm", "color", [("1", WASHES), ("5", WASHES)]),
    ("Warm white", "color", [("1", SPOTS)]),
    ("Steel", "color", [("2", SPOTS)]),
    ("Open white", "color", [("1", BEAMS), ("4", SPOTS + BEAMS)]),
    ("Amber", "color", [("4.5", BEAMS)]),
    ("Finale", "position", [("4", SPOTS + WASHES + BEAMS)]),
    ("Finale cross", "position", [("4.5", SPOTS + BEAMS)]),
    ("Narrow open", "beam", [("4", SPOTS)]),
]


def factor_palettes(cues):
    by_number = {c["number"]: c for c in cues}
    palettes = []
    for name, kind, uses in PALETTE_USES:
        per_fixture = {}
        for number, fids in uses:
            values = by_number[number]["values"]
            for fid in fids:
                moved = {a: values[fid].pop(a) for a in KIND_ATTRS[kind] if a in values[fid]}
                assert moved, "palette %s: cue %s has no %s values for %d" % (name, number, kind, fid)
                assert per_fixture.setdefault(fid, moved) == moved, "palette %s: two values for %d" % (name, fid)
                values[fid].setdefault("palettes", {})[kind] = name
        by_group = {}
        for group, members in GROUPS:
            if all(per_fixture.get(f) == per_fixture.get(members[0]) is not None for f in members):
                by_group[group] = per_fixture[members[0]]
                for f in members:
                    del per_fixture[f]
        palette = {"name": name, "kind": kind}
        if by_group:
            palette["groups"] = by_group
        if per_fixture:
            palette["fixtures"] = {str(f): v for f, v in sorted(per_fixture.items())}
        palettes.append(palette)
    return palettes


def resolve_values(show, fid, values):
    # A cue's values for one fixture with its palette references laid under them (show-format.md).
    out = {}
    for kind in ("all", "position", "color", "beam"):
        name = values.get("palettes", {}).get(kind)
        if name is None:
            continue
        palette = next(p for p in show["palettes"] if p["name"] == name and p["kind"] == kind)
        for group in show["groups"]:
            if fid in group["fixtures"] and group["name"] in palette.get("groups", {}):
                out.update(palette["groups"][group["name"]])
        out.update(palette.get("fixtures", {}).get(str(fid), {}))
    out.update({k: v for k, v in values.items() if k != "palettes"})
    return out


# --------------------------------------------------------------------------------------------
# JSON output a person can diff: 2-space indent, short arrays of numbers on one line.


def fmt_num(x):
    if isinstance(x, bool) or x is None:
        return json.dumps(x)
    if isinstance(x, int):
        return str(x)
    r = round(x, 4)
    return str(int(r)) + ".0" if r == int(r) else repr(r)


def inline_json(value):
    # One line; None when the value holds a list of objects or nested objects (those get blocks).
    if isinstance(value, dict):
        parts = []
        for k, v in value.items():
            if isinstance(v, dict):
                return None
            t = inline_json(v)
            if t is None:
                return None
            parts.append(json.dumps(k) + ": " + t)
        return "{ " + ", ".join(parts) + " }" if parts else "{}"
    if isinstance(value, (list, tuple)):
        parts = [inline_json(v) for v in value]
        if any(p is None or p.startswith("{") for p in parts):
            return None
        return "[" + ", ".join(parts) + "]"
    if isinstance(value, str):
        return json.dumps(value)
    return fmt_num(value)


def to_json(value, indent=0):
    pad = "  " * indent
    flat = inline_json(value)
    if flat is not None and len(flat) + 2 * indent < 100:
        return flat
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = [pad + "  " + json.dumps(k) + ": " + to_json(v, indent + 1) for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
            return "[" + ", ".join(fmt_num(v) for v in value) + "]"
        if all(isinstance(v, str) for v in value) and len(", ".join(value)) < 80:
            return "[" + ", ".join(json.dumps(v) for v in value) + "]"
        return "[\n" + ",\n".join(pad + "  " + to_json(v, indent + 1) for v in value) + "\n" + pad + "]"
    if isinstance(value, dict) and not value:
        return "{}"
    if isinstance(value, str):
        return json.dumps(value)
    return fmt_num(value)


def compact_values(values):
    # One fixture (or one fixture's cue values) on one line: small and easy to diff.
    return "{ " + ", ".join(json.dumps(k) + ": " + (compact_values(v) if isinstance(v, dict) else to_json(v))
                            for k, v in values.items()) + " }"


def write_show(path, cues, palettes):
    show = {
        "format": "haze-show", "version": 2,
        "venue": {"gltf": "venue/theatre.gltf"},
        "atmosphere": {"scattering": 0.03, "absorption": 0.0, "phase": "hazy", "g": 0.0, "ambient": 0.25},
        "cameras": [
            {"name": "FOH", "position": [0.0, 4.2, 10.5], "target": [0.0, 4.2, -3.0], "fov_y": 42.0},
            {"name": "Side", "position": [5.0, 6.0, 4.0], "target": [-1.5, 3.5, -4.0], "fov_y": 55.0},
            {"name": "Onstage", "position": [0.0, 1.7, -0.6], "target": [0.0, 7.0, -3.6], "fov_y": 75.0},
        ],
        "profiles": {k: "profiles/" + v[0] for k, v in PROFILES.items()},
    }
    fixtures = []
    next_addr = dict(FIRST_ADDRESS)
    for f in FIXTURES:
        mode = PROFILES[f["profile"]][1]["modes"][0]
        addr = next_addr[f["profile"]]
        next_addr[f["profile"]] += len(mode["channels"])
        fixtures.append({"id": f["id"], "name": f["name"], "profile": f["profile"], "mode": mode["name"],
                         "position": [round(c, 4) for c in f["position"]], "rotation": list(f["rotation"]),
                         "patch": {"universe": 1, "address": addr}})
    # Written by hand so that each fixture and each cue value is one block/line.
    out = ["{"]
    for k, v in show.items():
        out.append("  " + json.dumps(k) + ": " + to_json(v, 1) + ",")
    out.append('  "fixtures": [')
    out.append(",\n".join("    " + compact_values(f) for f in fixtures))
    out.append("  ],")
    out.append('  "groups": [')
    out.append(",\n".join("    " + compact_values({"name": g, "fixtures": m}) for g, m in GROUPS))
    out.append("  ],")
    out.append('  "palettes": [')
    pal_txt = []
    for p in palettes:
        parts = ['    { "name": %s, "kind": %s' % (json.dumps(p["name"]), json.dumps(p["kind"]))]
        for section in ("groups", "fixtures"):
            if section in p:
                parts.append('      "%s": {\n' % section + ",\n".join(
                    "        %s: %s" % (json.dumps(k), compact_values(v)) for k, v in p[section].items()) + " }")
        pal_txt.append(",\n".join(parts) + " }")
    out.append(",\n".join(pal_txt))
    out.append("  ],")
    out.append('  "cue_lists": [')
    out.append('    { "name": "Main",')
    out.append('      "cues": [')
    cue_txt = []
    for c in cues:
        head = ", ".join(json.dumps(k) + ": " + to_json(c[k]) for k in ("number", "label", "fade", "delay", "follow"))
        if "effects" in c:
            head += ',\n          "effects": [' + ", ".join(compact_values(e) for e in c["effects"]) + "]"
        vals = ",\n".join('            "%d": %s' % (fid, compact_values(vv)) for fid, vv in sorted(c["values"].items()))
        cue_txt.append("        { " + head + ',\n          "values": {\n' + vals + "\n          } }")
    out.append(",\n".join(cue_txt))
    out.append("      ] }")
    out.append("  ]")
    out.append("}")
    text = "\n".join(out) + "\n"
    json.loads(text)  # must parse
    with open(path, "w") as f:
        f.write(text)
    return fixtures


# --------------------------------------------------------------------------------------------


def check_show(show_path, tris, targets):
    with open(show_path) as f:
        show = json.load(f)
    ok = True
    profiles = {}
    for name, rel in show["profiles"].items():
        with open(os.path.join(os.path.dirname(show_path), rel)) as f:
            profiles[name] = json.load(f)
        pdir = os.path.dirname(os.path.join(os.path.dirname(show_path), rel))
        for wheel in profiles[name].get("gobo_wheels", []):
            for slot in wheel["slots"]:
                if "image" in slot:
                    assert os.path.exists(os.path.join(pdir, slot["image"])), slot["image"]
    # Patch: no two fixtures share a DMX slot.
    used = {}
    for f in show["fixtures"]:
        prof = profiles[f["profile"]]
        mode = next(m for m in prof["modes"] if m["name"] == f["mode"])
        p = f["patch"]
        last = p["address"] + len(mode["channels"]) - 1
        assert 1 <= p["address"] and last <= 512, "patch of %d off the universe" % f["id"]
        for a in range(p["address"], last + 1):
            assert (p["universe"], a) not in used, "fixtures %d and %d overlap at %d" % (used[(p["universe"], a)], f["id"], a)
            used[(p["universe"], a)] = f["id"]
    # Tracking: the full state of each cue, every value in its profile's range, every beam axis cast.
    state = {f["id"]: {} for f in show["fixtures"]}
    fixtures = {f["id"]: f for f in show["fixtures"]}
    aimed = {}   # fixture id -> its target in the cue that last set its pan/tilt
    for cue in show["cue_lists"][0]["cues"]:
        aimed.update(targets.get(cue["number"], {}))
        print("Cue %s %s (fade %.1f s, delay %.1f s, follow %s)" % (cue["number"], cue["label"], cue["fade"],
                                                                   cue["delay"], cue["follow"]))
        for fid, vals in cue["values"].items():
            state[int(fid)].update(resolve_values(show, int(fid), vals))
        for fid in sorted(state):
            s, f = state[fid], fixtures[fid]
            prof = profiles[f["profile"]]
            pan, tilt = s.get("pan", 0.0), s.get("tilt", 0.0)
            assert prof["pan"]["min"] <= pan <= prof["pan"]["max"], (fid, pan)
            assert prof["tilt"]["min"] <= tilt <= prof["tilt"]["max"], (fid, tilt)
            zoom = s.get("zoom", prof["field_angle"])
            assert prof["zoom"]["min"] <= zoom <= prof["zoom"]["max"], (fid, zoom)
            assert 0.0 <= s.get("intensity", 0.0) <= 1.0 and 0.0 <= s.get("iris", 1.0) <= 1.0
            assert all(0.0 <= c <= 1.0 for c in s.get("color", [1, 1, 1]))
            if "gobo" in s:
                names = [sl["name"] for w in prof.get("gobo_wheels", [])[:1] for sl in w["slots"]] + ["Open"]
                assert s["gobo"] in names, (fid, s["gobo"])
            if s.get("intensity", 0.0) <= 0.0:
                continue
            zb, m = beam_axis(f["rotation"], pan, tilt)
            lens = add(f["position"], m3v(m, prof["lens_offset"]))
            dist, hit = raycast(tris, lens, zb)
            where = "nothing" if hit is None else "%-22s at (%6.2f, %5.2f, %6.2f), %5.1f m" % (
                hit, *add(lens, mul(zb, dist)), dist)
            print("  %d %-13s pan %7.1f tilt %7.1f  I %.2f  zoom %4.1f  %-6s -> %s" % (
                fid, f["name"], pan, tilt, s["intensity"], zoom, s.get("gobo", ""), where))
            # The axis must pass within 5 cm of its target, and nothing may stop it more than
            # 30 cm short of the target (targets on a curved or thick piece lie inside it).
            tgt = aimed[fid]
            if hit and hit.startswith("column") and abs(tgt[0] - COLUMN["x"]) + abs(tgt[2] - COLUMN["z"]) < 1e-9:
                tgt = add(lens, mul(zb, dist))
            miss = length(cross(sub(tgt, lens), zb))
            short = length(sub(tgt, lens)) - (dist if hit else 1e9)
            if miss > 0.05 or short > 0.3:
                print("    !! beam axis of %d misses its target %s by %.2f m or stops %.2f m short" % (
                    fid, tuple(round(c, 2) for c in tgt), miss, short))
                ok = False
    return ok


def main():
    os.makedirs(os.path.join(DEMO, "venue"), exist_ok=True)
    os.makedirs(os.path.join(DEMO, "profiles"), exist_ok=True)
    os.makedirs(os.path.join(DEMO, "gobos"), exist_ok=True)

    for _, fname, make in GOBOS:
        write_png(os.path.join(DEMO, "gobos", fname), GOBO_SIZE, GOBO_SIZE, gobo_image(make()), 1)
    tex_rows = deck_texture()
    write_png(os.path.join(DEMO, "venue", "deck_planks.png"), 256, 256, tex_rows, 3)
    mean = sum(srgb_to_linear(b / 255.0) for r in tex_rows for b in r) / (256 * 256 * 3)
    print("deck texture: linear mean albedo %.3f" % mean)

    g = build_venue()
    doc, blob = g.finish("theatre.bin")
    gltf_path = os.path.join(DEMO, "venue", "theatre.gltf")
    with open(os.path.join(DEMO, "venue", "theatre.bin"), "wb") as f:
        f.write(blob)
    with open(gltf_path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    doc = verify_gltf(gltf_path)
    tris = world_triangles(doc, g.mesh_data)
    lo = [min(min(t[k][a] for k in range(3)) for t in tris) for a in range(3)]
    hi = [max(max(t[k][a] for k in range(3)) for t in tris) for a in range(3)]
    print("venue: %d nodes, %d meshes, %d triangles, bounds %s .. %s, gltf %d bytes, bin %d bytes" % (
        len(doc["nodes"]), len(doc["meshes"]), len(tris), [round(x, 2) for x in lo], [round(x, 2) for x in hi],
        os.path.getsize(gltf_path), len(blob)))

    for key, (fname, prof) in PROFILES.items():
        with open(os.path.join(DEMO, "profiles", fname), "w") as f:
            f.write(to_json(prof) + "\n")
    cues, targets = build_cues()
    show_path = os.path.join(DEMO, "demo.haze.json")
    write_show(show_path, cues, factor_palettes(cues))
    for f in FIXTURES:
        print("fixture %d %-13s at %s rotation %s" % (f["id"], f["name"], tuple(round(c, 3) for c in f["position"]),
                                                       f["rotation"]))
    # Cameras: the line of sight to the target must be clear.
    with open(show_path) as fh:
        show = json.load(fh)
    for cam in show["cameras"]:
        d = sub(cam["target"], cam["position"])
        dist, hit = raycast(tris, tuple(cam["position"]), unit(d))
        print("camera %-8s looks at %s: first surface %s at %.1f m (target %.1f m)" % (
            cam["name"], cam["target"], hit, dist or -1, length(d)))
        assert hit is None or dist >= length(d) - 0.3, "camera %s does not see its target" % cam["name"]
    if not check_show(show_path, tris, targets):
        sys.exit("some beam axes are blocked: see above")
    print("all checks passed")


if __name__ == "__main__":
    main()
