#!/usr/bin/env python3
"""Converts a radiometric PFM (haze's float output) to a PNG for looking at: exposure, the same
ACES fit as shaders/post.frag.glsl, sRGB. Standard library only.
usage: pfm_to_png.py IN.pfm OUT.png [--ev EV] [--key NITS]"""
import struct, sys, zlib

def read_pfm(path):
    with open(path, 'rb') as f:
        data = f.read()
    parts, pos = [], 0
    while len(parts) < 4:
        while data[pos:pos + 1].isspace(): pos += 1
        end = pos
        while not data[end:end + 1].isspace(): end += 1
        parts.append(data[pos:end].decode()); pos = end
    pos += 1
    w, h, scale = int(parts[1]), int(parts[2]), float(parts[3])
    fmt = '<' if scale < 0 else '>'
    vals = struct.unpack(fmt + 'f' * (w * h * 3), data[pos:pos + w * h * 12])
    rows = [vals[(h - 1 - y) * w * 3:(h - y) * w * 3] for y in range(h)]  # PFM is bottom-up
    return w, h, rows

def encode(x):
    x = max(0.0, min(1.0, (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)))
    x = x * 12.92 if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return int(round(x * 255))

def main():
    src, dst = sys.argv[1], sys.argv[2]
    ev = float(sys.argv[sys.argv.index('--ev') + 1]) if '--ev' in sys.argv else 0.0
    key = float(sys.argv[sys.argv.index('--key') + 1]) if '--key' in sys.argv else 50.0
    w, h, rows = read_pfm(src)
    k = 2.0 ** ev / key
    raw = b''.join(b'\x00' + bytes(encode(v * k) for v in row) for row in rows)
    def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) + \
        chunk(b'IDAT', zlib.compress(raw, 6)) + chunk(b'IEND', b'')
    with open(dst, 'wb') as f:
        f.write(png)

if __name__ == '__main__':
    main()
