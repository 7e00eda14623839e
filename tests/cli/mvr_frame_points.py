#!/usr/bin/env python3
"""mvr_frame_points.py RIG.mvr SHOW.haze.json CAMERA WIDTH HEIGHT

Projects an MVR rig's fixtures and where their beams land through a camera of a show, and
prints "INSIDE TOTAL" (then one line per point outside the frame). Everything but the camera is
read from the MVR itself, with a walk of its own: the matrices composed down the scene tree, a
fixture's beam along its -Z at rest (GDTF), landing on its <Focus> point, else where that axis
meets the MVR floor z = 0 within 30 m (a beam that never does adds no point). MVR millimetres,
Z up, map to haze metres, Y up, as (x, z, -y) / 1000 (docs/mvr.md). The camera is the pinhole of
docs/physics.md: fov_y vertical, the width from the image's aspect, up +Y unless it says."""
import json
import math
import re
import sys
import xml.etree.ElementTree as ET
import zipfile


def parse_matrix(text):
    nums = [float(v) for v in re.findall(r"[-+0-9.eE]+", text or "")]
    if len(nums) != 12:
        return None
    u, v, w, o = nums[0:3], nums[3:6], nums[6:9], nums[9:12]
    # Columns u, v, w, o of a 4x4 (row-major list of rows).
    return [[u[r], v[r], w[r], o[r]] for r in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def mul(a, b):
    return [[sum(a[r][k] * b[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


IDENTITY = [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]


def walk(node, world, fixtures, focus):
    for child in node:
        tag = child.tag
        m = world
        mat = child.find("Matrix")
        if mat is not None and parse_matrix(mat.text) is not None:
            m = mul(world, parse_matrix(mat.text))
        if tag == "Fixture":
            f = child.find("Focus")
            fixtures.append((m, f.text.strip() if f is not None and f.text else None))
        elif tag == "FocusPoint":
            focus[child.get("uuid", "").upper()] = m
        children = child.find("ChildList")
        if children is not None:
            walk(children, m, fixtures, focus)


def to_haze(p):
    return (p[0] / 1000.0, p[2] / 1000.0, -p[1] / 1000.0)


def rig_points(mvr_path):
    xml = zipfile.ZipFile(mvr_path).read("GeneralSceneDescription.xml")
    scene = ET.fromstring(xml).find("Scene")
    fixtures, focus = [], {}
    for layer in scene.find("Layers"):
        mat = layer.find("Matrix")
        m = mul(IDENTITY, parse_matrix(mat.text)) if mat is not None and parse_matrix(mat.text) else IDENTITY
        walk(layer.find("ChildList") if layer.find("ChildList") is not None else [], m, fixtures, focus)
    points = []
    for m, focus_uuid in fixtures:
        origin = [m[r][3] for r in range(3)]
        points.append(("fixture", to_haze(origin)))
        if focus_uuid and focus_uuid.upper() in focus:
            fm = focus[focus_uuid.upper()]
            points.append(("focus point", to_haze([fm[r][3] for r in range(3)])))
            continue
        down = [-m[r][2] for r in range(3)]
        norm = math.sqrt(sum(d * d for d in down))
        if norm == 0.0 or down[2] >= -1e-6:
            continue
        t = -origin[2] / down[2]  # mm along the unit-free axis
        if 0.0 < t * norm <= 30000.0:
            points.append(("beam landing", to_haze([origin[r] + t * down[r] for r in range(3)])))
    return points


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def main():
    mvr, show_path, camera, width, height = sys.argv[1:6]
    show = json.load(open(show_path))
    cam = next(c for c in show["cameras"] if c["name"] == camera)
    eye = cam["position"]
    forward = normalize([t - e for t, e in zip(cam["target"], eye)])
    right = normalize(cross(forward, cam.get("up", [0.0, 1.0, 0.0])))
    up = cross(right, forward)
    half_y = math.tan(math.radians(cam["fov_y"]) / 2.0)
    half_x = half_y * float(width) / float(height)
    points = rig_points(mvr)
    outside = []
    for kind, p in points:
        d = [a - b for a, b in zip(p, eye)]
        z = dot(d, forward)
        x = dot(d, right) / (z * half_x) if z > 0 else float("inf")
        y = dot(d, up) / (z * half_y) if z > 0 else float("inf")
        if not (abs(x) <= 1.0 and abs(y) <= 1.0):
            outside.append("%s (%.2f, %.2f, %.2f) m: frame x %.2f y %.2f (inside is -1..1)" % (kind, p[0], p[1], p[2], x, y))
    print(len(points) - len(outside), len(points))
    for line in outside[:10]:
        print(line)


main()
