#!/usr/bin/env python3
"""exr_vs_pfm.py IMAGE.exr DECODED.raw IMAGE.pfm half|float: checks an EXR written by haze
against the PFM of the same frame. The pixels come from FFmpeg's own EXR decoder (DECODED.raw,
gbrpf32le), a second implementation next to OpenEXR; the header is read here, by hand. Prints
one line per failed check and "max relative error E" last; exits 1 on any failure."""
import array
import struct
import sys

exr_path, raw_path, pfm_path, pixel = sys.argv[1:5]
failures = []


def read_pfm(path):
    data = open(path, "rb").read()
    magic, size, scale, body = data.split(b"\n", 3)
    assert magic == b"PF" and float(scale) < 0, path + ": expected a little-endian colour PFM"
    w, h = map(int, size.split())
    values = array.array("f")
    values.frombytes(body[:w * h * 12])
    rows = [values[y * w * 3:(y + 1) * w * 3] for y in range(h)]
    return w, h, rows[::-1]  # PFM stores the bottom row first


def exr_header(path):
    data = open(path, "rb").read()
    magic, version = struct.unpack("<II", data[:8])
    assert magic == 20000630, path + ": not an OpenEXR file"
    pos, attrs = 8, {}
    while data[pos] != 0:
        name_end = data.index(b"\0", pos)
        type_end = data.index(b"\0", name_end + 1)
        name, kind = data[pos:name_end].decode(), data[name_end + 1:type_end].decode()
        (size,) = struct.unpack("<i", data[type_end + 1:type_end + 5])
        attrs[name] = (kind, data[type_end + 5:type_end + 5 + size])
        pos = type_end + 5 + size
    return attrs


w, h, pfm = read_pfm(pfm_path)
attrs = exr_header(exr_path)

# Channels: R, G, B of the asked pixel type (chlist: name\0, int type, 12 more bytes each).
kind, body = attrs["channels"]
channels, pos = {}, 0
while body[pos] != 0:
    end = body.index(b"\0", pos)
    channels[body[pos:end].decode()] = struct.unpack("<i", body[end + 1:end + 5])[0]
    pos = end + 17
want_type = {"half": 1, "float": 2}[pixel]
if channels != {"R": want_type, "G": want_type, "B": want_type}:
    failures.append("channels %s, expected R, G, B of type %d" % (channels, want_type))
kind, body = attrs.get("chromaticities", ("", b""))
rec709 = (0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290)
if kind != "chromaticities" or any(abs(a - b) > 1e-6 for a, b in zip(struct.unpack("<8f", body), rec709)):
    failures.append("chromaticities missing or not Rec. 709 / D65")
kind, body = attrs.get("whiteLuminance", ("", b""))
if kind != "float" or struct.unpack("<f", body)[0] != 1.0:
    failures.append("whiteLuminance missing or not 1 (cd/m^2)")
kind, body = attrs.get("comments", ("", b""))
print("comments: " + body.decode())

# FFmpeg's planar float output: all G, then all B, then all R, rows top first.
raw = array.array("f")
raw.frombytes(open(raw_path, "rb").read())
if len(raw) != w * h * 3:
    failures.append("decoded %d values, expected %dx%dx3" % (len(raw), w, h))
else:
    plane = {"G": 0, "B": 1, "R": 2}
    worst = 0.0
    for y in range(h):
        for x in range(w):
            for c, name in enumerate("RGB"):
                v = pfm[y][x * 3 + c]
                d = abs(raw[plane[name] * w * h + y * w + x] - v)
                # Half rounds to nearest: at most half a unit in the last of 10 mantissa bits
                # (2^-11 relative), or 2^-25 absolute among the subnormals; float is exact.
                allowed = max(abs(v) * 2.0 ** -11, 2.0 ** -25) if pixel == "half" else 0.0
                if d > allowed:
                    failures.append("pixel (%d, %d) %s: EXR %g, PFM %g" % (x, y, name, v + d, v))
                if v > 2.0 ** -14:
                    worst = max(worst, d / abs(v))
    print("max relative error %.3g" % worst)
for f in failures[:10]:
    print("FAIL " + f)
sys.exit(1 if failures else 0)
