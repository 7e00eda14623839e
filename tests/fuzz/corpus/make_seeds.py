# Writes the fuzz seed corpus (tests/fuzz/corpus/<parser>/): small hand-made files, ok-* valid
# and bad-* broken in one known way each. Run with python3 from anywhere; the output is
# deterministic (zip entries carry a fixed date): rerunning changes nothing unless this did.
import base64, json, os, struct, zipfile

HERE = os.path.dirname(os.path.abspath(__file__))

def put(parser, name, data):
    os.makedirs(os.path.join(HERE, parser), exist_ok=True)
    if isinstance(data, str):
        data = data.encode('utf-8')
    with open(os.path.join(HERE, parser, name), 'wb') as f:
        f.write(data)

def zipped(items):
    import io
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, 'w', zipfile.ZIP_DEFLATED) as z:
        for name, data in items:
            info = zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
    return buf.getvalue()

# ---- IES ----
def ies(vs, hs, rows, tilt='TILT=NONE', manufac='Haze Tests'):
    out = 'IESNA:LM-63-2002\n[TEST] fuzz seed\n[MANUFAC] %s\n[LUMINAIRE] Seed\n%s\n' % (manufac, tilt)
    out += '1 -1 1 %d %d 1 2 0 0 0\n1.0 1.0 100\n' % (len(vs), len(hs))
    out += ' '.join(str(v) for v in vs) + '\n' + ' '.join(str(h) for h in hs) + '\n'
    for r in rows:
        out += ' '.join(str(x) for x in r) + '\n'
    return out
put('ies', 'ok-axial.ies', ies([0, 10, 20, 30, 45, 90], [0], [[1000, 900, 500, 200, 50, 0]]))
put('ies', 'ok-quadrant.ies', ies([0, 30, 60, 90], [0, 45, 90], [[800, 600, 100, 0], [700, 500, 80, 0], [600, 400, 60, 0]]))
put('ies', 'bad-no-tilt.ies', 'IESNA:LM-63-2002\n[MANUFAC] x\n1 -1 1 2 1 1 2 0 0 0\n')
put('ies', 'bad-huge-counts.ies', ies([0, 90], [0], [[1, 0]]).replace('1 -1 1 2 1 ', '1 -1 1 99999999 99999999 '))

# ---- EULUMDAT ----
def ldt(isym, mc, gammas, value):
    dc = 360.0 / mc
    o = 'Haze Tests\n1\n%d\n%d\n%g\n%d\n%g\nreport\nSeed\nK-1\nseed.ldt\n2026-01-01\n' % (
        isym, mc, dc, len(gammas), gammas[1] - gammas[0])
    o += '100\n100\n50\n100\n100\n0\n0\n0\n0\n100\n100\n1.0\n0\n'
    o += '1\n1\nLED\n1000\n3000\n90\n100\n' + '0.5\n' * 10
    o += ''.join('%g\n' % (k * dc) for k in range(mc)) + ''.join('%g\n' % g for g in gammas)
    planes = {0: mc, 1: 1, 2: mc // 2 + 1, 3: mc // 2 + 1, 4: mc // 4 + 1}[isym]
    for _ in range(planes):
        o += ''.join('%g\n' % value(g) for g in gammas)
    return o
put('ldt', 'ok-axial.ldt', ldt(1, 4, [0, 15, 30, 45, 60, 90], lambda g: max(0, 500 - 6 * g)))
put('ldt', 'ok-full.ldt', ldt(0, 4, [0, 30, 60, 90], lambda g: max(0, 400 - 4 * g)))
put('ldt', 'bad-truncated.ldt', ldt(1, 4, [0, 30, 60, 90], lambda g: 1)[:120])

# ---- native profile JSON ----
wash = {"format": "haze-fixture", "version": 1, "manufacturer": "haze seed", "name": "Wash",
        "photometry": {"beam_angle": 20.0, "field_angle": 35.0, "peak_candela": 20000.0},
        "lens_offset": [0.0, -0.2, 0.0], "field_angle": 35.0, "zoom": {"min": 10.0, "max": 60.0},
        "pan": {"min": -270.0, "max": 270.0}, "tilt": {"min": -135.0, "max": 135.0},
        "color": {"mixing": "rgb"},
        "modes": [{"name": "Standard", "channels": ["Dimmer", "Pan", "Pan fine", "Tilt", "Tilt fine", "Red", "Green", "Blue", "Zoom"]}]}
put('profile_json', 'ok-wash.json', json.dumps(wash, indent=2))
spot = dict(wash, name="Spot", color={"mixing": "none"},
            color_wheels=[{"name": "Colour", "slots": [{"name": "Open"}, {"name": "Red", "color": [1, 0, 0]}]}])
put('profile_json', 'ok-colour-wheel.json', json.dumps(spot))
put('profile_json', 'bad-ies-missing.json', json.dumps(dict(wash, photometry={"ies": "missing.ies"})))
put('profile_json', 'bad-not-json.json', '{"format": "haze-fixture", ')

# ---- show ----
show = {"format": "haze-show", "version": 1,
        "atmosphere": {"scattering": 0.03, "absorption": 0, "phase": "hazy", "g": 0, "ambient": 0.02},
        "cameras": [{"name": "FOH", "position": [0, 4, 18], "target": [0, 2, 0], "fov_y": 40}],
        "profiles": {"par": {"inline": {"format": "haze-fixture", "version": 1, "manufacturer": "seed", "name": "Par",
                                        "photometry": {"beam_angle": 30, "field_angle": 50, "peak_candela": 5000},
                                        "field_angle": 50, "zoom": {"min": 50, "max": 50}, "color": {"mixing": "rgb"},
                                        "modes": [{"name": "RGB", "channels": ["Dimmer", "Red", "Green", "Blue"]}]}}},
        "fixtures": [{"id": 1, "profile": "par", "mode": "RGB", "position": [0, 6, 0], "patch": {"universe": 1, "address": 1}},
                     {"id": 2, "profile": "par", "mode": "RGB", "position": [2, 6, 0], "patch": {"universe": 1, "address": 5}}],
        "cue_lists": [{"name": "Main", "cues": [
            {"number": "1", "fade": 2, "values": {"1": {"intensity": 1, "color": [1, 0.5, 0.2]}}},
            {"number": "1.5", "fade": 1, "delay": 0.5, "follow": 2, "values": {"2": {"intensity": 0.5}}},
            {"number": "2", "fade": 3, "values": {"1": {"intensity": 0}}}]}]}
put('show', 'ok-two-pars.haze.json', json.dumps(show, indent=2))
put('show', 'bad-cues.haze.json', json.dumps(dict(show, cue_lists=[{"name": "Main", "cues": [
    {"number": "2", "fade": -3, "values": {"7": {"pan": 300}}}, {"number": "1", "values": {}}]}])))
put('show', 'bad-newer-version.haze.json', '{"format": "haze-show", "version": 99}')

# ---- venue (glTF) ----
positions = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0)
uvs = struct.pack('<6f', 0, 0, 1, 0, 0, 1)
indices = struct.pack('<3H', 0, 1, 2) + b'\0\0'
# A 2x2 grey+alpha PNG (the one tests/unit/gdtf uses).
png = bytes([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
             0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x04, 0x00, 0x00, 0x00, 0xd8, 0xbf, 0xc5, 0xaf, 0x00, 0x00, 0x00,
             0x10, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xff, 0x9f, 0x01, 0x04, 0x1b, 0xfe, 0x03, 0x00, 0x1c,
             0xee, 0x05, 0x7c, 0x99, 0xde, 0x6c, 0x65, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60,
             0x82])

def gltf(buffer, accessors, views, textured=True, uri=None, extra_nodes=None):
    g = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
         "nodes": [{"mesh": 0, "translation": [0, 1, 0]}],
         "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
         "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}}],
         "buffers": [{"byteLength": len(buffer),
                      "uri": uri if uri else "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
         "bufferViews": views, "accessors": accessors}
    if textured:
        g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
        g["textures"] = [{"source": 0}]
        g["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}]
    if extra_nodes:
        g["nodes"] += extra_nodes
    return g

buf = positions + uvs + indices
views = [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24},
         {"buffer": 0, "byteOffset": 60, "byteLength": 6}]
accs = [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
        {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}]
put('venue', 'ok-triangle.gltf', json.dumps(gltf(buf, accs, views)))
nan_uvs = struct.pack('<6f', float('nan'), 0, 1, float('nan'), float('inf'), 1)
put('venue', 'ok-nan-uv.gltf', json.dumps(gltf(positions + nan_uvs + indices, accs, views)))
wrap = [dict(accs[0], byteOffset=2**64 - 12)] + accs[1:]
put('venue', 'bad-offset-wraps.gltf', json.dumps(gltf(buf, wrap, views, textured=False)))
huge_views = [dict(views[0], byteStride=16)] + views[1:]
huge = [dict(accs[0], count=2**60 + 1)] + accs[1:]
put('venue', 'bad-count-huge.gltf', json.dumps(gltf(buf, huge, huge_views, textured=False)))
put('venue', 'bad-external-uri.gltf', json.dumps(gltf(buf, accs, views, textured=False, uri="tri.bin")))
bad_idx = struct.pack('<3H', 0, 1, 7) + b'\0\0'
put('venue', 'bad-index-past-vertices.gltf', json.dumps(gltf(positions + uvs + bad_idx, accs, views, textured=False)))

def glb(doc, binary):
    j = json.dumps(doc).encode()
    j += b' ' * (-len(j) % 4)
    binary += b'\0' * (-len(binary) % 4)
    body = struct.pack('<II', len(j), 0x4E4F534A) + j + struct.pack('<II', len(binary), 0x004E4942) + binary
    return b'glTF' + struct.pack('<II', 2, 12 + len(body)) + body
doc = gltf(buf, accs, views, textured=False)
del doc["buffers"][0]["uri"]
put('venue', 'ok-triangle.glb', glb(doc, buf))

# ---- GDTF ----
def head_xml(name='Seed Head', wheel_slot='Dots'):
    return '''<?xml version="1.0" encoding="UTF-8"?>
<GDTF DataVersion="1.2">
  <FixtureType Name="%s" Manufacturer="Haze Seeds">
    <Wheels><Wheel Name="G1"><Slot Name="Open"/><Slot Name="%s" MediaFileName="dots"/></Wheel></Wheels>
    <Geometries>
      <Geometry Name="Base" Position="{1,0,0,0}{0,1,0,0}{0,0,1,0}{0,0,0,1}">
        <Axis Name="Yoke" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.2}{0,0,0,1}">
          <Axis Name="Head" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.1}{0,0,0,1}">
            <Beam Name="Beam" Position="{1,0,0,0}{0,1,0,0}{0,0,1,-0.3}{0,0,0,1}" BeamAngle="20" FieldAngle="30" LuminousFlux="5000" BeamType="Wash"/>
          </Axis>
        </Axis>
      </Geometry>
    </Geometries>
    <DMXModes>
      <DMXMode Name="Default" Geometry="Base">
        <DMXChannels>
          <DMXChannel DMXBreak="1" Offset="1,2" Geometry="Yoke"><LogicalChannel Attribute="Pan">
            <ChannelFunction Attribute="Pan" DMXFrom="0/2" PhysicalFrom="-270" PhysicalTo="270"/></LogicalChannel></DMXChannel>
          <DMXChannel DMXBreak="1" Offset="3" Geometry="Beam"><LogicalChannel Attribute="Dimmer">
            <ChannelFunction Attribute="Dimmer" DMXFrom="0/1" PhysicalFrom="0" PhysicalTo="1"/></LogicalChannel></DMXChannel>
          <DMXChannel DMXBreak="1" Offset="4" Geometry="Beam"><LogicalChannel Attribute="Gobo1">
            <ChannelFunction Attribute="Gobo1" DMXFrom="0/1" Wheel="G1">
              <ChannelSet DMXFrom="0/1" Name="Open" WheelSlotIndex="1"/>
              <ChannelSet DMXFrom="10/1" Name="Dots" WheelSlotIndex="2"/>
            </ChannelFunction></LogicalChannel></DMXChannel>
        </DMXChannels>
      </DMXMode>
    </DMXModes>
  </FixtureType>
</GDTF>
''' % (name, wheel_slot)
head = zipped([('description.xml', head_xml()), ('wheels/dots.png', png)])
put('gdtf', 'ok-head.gdtf', head)
put('gdtf', 'ok-latin1-names.gdtf', zipped([('description.xml', head_xml('B\xfchne', 'Kreis\xe9').encode('latin-1')),
                                            ('wheels/dots.png', png)]))
put('gdtf', 'bad-no-description.gdtf', zipped([('readme.txt', 'no description')]))
put('gdtf', 'bad-not-zip.gdtf', 'this is not a zip archive')
# gdtf_xml: description.xml alone (the harness zips it with wheels/dots.png).
put('gdtf_xml', 'ok-head.xml', head_xml())
put('gdtf_xml', 'ok-latin1-names.xml', head_xml('B\xfchne', 'Kreis\xe9').encode('latin-1'))
put('gdtf_xml', 'bad-no-fixture-type.xml', '<?xml version="1.0" encoding="UTF-8"?>\n<GDTF DataVersion="1.2"></GDTF>\n')
put('gdtf_xml', 'bad-beam-angle.xml', head_xml().replace('BeamAngle="20"', 'BeamAngle="abc"'))

# ---- MVR ----
scene = '''<?xml version="1.0"?>
<GeneralSceneDescription verMajor="1" verMinor="5">
<Scene><AUXData></AUXData><Layers><Layer name="L" uuid="1"><ChildList>
<Fixture name="Spot 1" uuid="u-1"><Matrix>{1,0,0}{0,1,0}{0,0,1}{0,0,6000}</Matrix><GDTFSpec>head.gdtf</GDTFSpec>
<GDTFMode>Default</GDTFMode><FixtureID>1</FixtureID><Addresses><Address break="0">1</Address></Addresses></Fixture>
<Fixture name="Spot 2" uuid="u-2"><Matrix>{1,0,0}{0,1,0}{0,0,1}{2000,0,6000}</Matrix><GDTFSpec>head.gdtf</GDTFSpec>
<GDTFMode>Default</GDTFMode><FixtureID>2</FixtureID><Addresses><Address break="0">11</Address></Addresses></Fixture>
</ChildList></Layer></Layers></Scene>
</GeneralSceneDescription>
'''
put('mvr', 'ok-two-spots.mvr', zipped([('GeneralSceneDescription.xml', scene), ('head.gdtf', head)]))
put('mvr', 'bad-no-scene.mvr', zipped([('head.gdtf', head)]))
put('mvr', 'bad-malformed-xml.mvr', zipped([('GeneralSceneDescription.xml', scene[:300])]))

# ---- Art-Net ----
def artdmx(data, seq=1, subuni=0, net=0, protver=14):
    return b'Art-Net\0' + bytes([0x00, 0x50, protver >> 8, protver & 0xff, seq, 0, subuni, net,
                                 len(data) >> 8, len(data) & 0xff]) + bytes(data)
put('artnet', 'ok-full-universe.bin', artdmx([i % 256 for i in range(512)]))
put('artnet', 'ok-short.bin', artdmx([255, 128], seq=0, subuni=3))
put('artnet', 'bad-odd-length.bin', artdmx([1, 2, 3]))
put('artnet', 'bad-id.bin', b'Art-Nat\0' + artdmx([0, 0])[8:])

# ---- sACN ----
def sacn(slots, universe=1, priority=100, options=0, start=0):
    size = 126 + len(slots)
    p = bytearray(size)
    def put16(at, v):
        p[at] = (v >> 8) & 0xff; p[at + 1] = v & 0xff
    put16(0, 0x0010); put16(2, 0)
    p[4:16] = b'ASC-E1.17\0\0\0'
    put16(16, 0x7000 | (size - 16)); p[21] = 0x04
    p[22:38] = b'\x11' * 16
    put16(38, 0x7000 | (size - 38)); p[43] = 0x02
    name = b'seed console'
    p[44:44 + len(name)] = name
    p[108] = priority; put16(109, 0); p[111] = 7; p[112] = options; put16(113, universe)
    put16(115, 0x7000 | (size - 115)); p[117] = 0x02; p[118] = 0xA1; put16(119, 0); put16(121, 1)
    put16(123, len(slots) + 1); p[125] = start
    p[126:] = bytes(slots)
    return bytes(p)
put('sacn', 'ok-full-universe.bin', sacn([i % 256 for i in range(512)]))
put('sacn', 'ok-short-preview.bin', sacn([10, 20, 30], universe=7, options=0x80))
put('sacn', 'bad-priority.bin', sacn([0] * 8, priority=201))
put('sacn', 'bad-truncated.bin', sacn([0] * 8)[:100])
put('sacn', 'ok-per-slot-priority.bin', sacn([200, 0, 100, 50], start=0xDD))
put('sacn', 'bad-per-slot-priority.bin', sacn([200, 201], start=0xDD))

# ---- sACN extended: synchronization and universe discovery ----
def extended(body_len, vector):
    size = 38 + body_len
    p = bytearray(size)
    def put16(at, v):
        p[at] = (v >> 8) & 0xff; p[at + 1] = v & 0xff
    put16(0, 0x0010); put16(2, 0)
    p[4:16] = b'ASC-E1.17\0\0\0'
    put16(16, 0x7000 | (size - 16)); p[21] = 0x08
    p[22:38] = b'\x22' * 16
    put16(38, 0x7000 | (size - 38)); p[43] = vector
    return p, put16
def sacn_sync(address, seq=3):
    p, put16 = extended(11, 0x01)
    p[44] = seq; put16(45, address)
    return bytes(p)
def sacn_discovery(universes, page=0, last=0):
    p, put16 = extended(82 + 2 * len(universes), 0x02)
    name = b'seed console'
    p[44:44 + len(name)] = name
    put16(112, 0x7000 | (len(p) - 112)); p[117] = 0x01; p[118] = page; p[119] = last
    for i, u in enumerate(universes):
        put16(120 + 2 * i, u)
    return bytes(p)
put('sacn_extended', 'ok-sync.bin', sacn_sync(7000))
put('sacn_extended', 'ok-discovery.bin', sacn_discovery(list(range(1, 40)) + [63999], page=1, last=2))
put('sacn_extended', 'bad-sync-address.bin', sacn_sync(0))
put('sacn_extended', 'bad-discovery-page.bin', sacn_discovery([1], page=3, last=2))
put('sacn_extended', 'bad-data-packet.bin', sacn([1, 2, 3]))

# ---- ArtTimeCode ----
def art_timecode(h, m, s, f, kind=1):
    return b'Art-Net\0' + bytes([0x00, 0x97, 0, 14, 0, 0, f, s, m, h, kind])
put('artnet_timecode', 'ok-ebu.bin', art_timecode(1, 2, 3, 24))
put('artnet_timecode', 'ok-smpte.bin', art_timecode(23, 59, 59, 29, kind=3))
put('artnet_timecode', 'bad-24-hours.bin', art_timecode(24, 0, 0, 0))
put('artnet_timecode', 'bad-type.bin', art_timecode(0, 0, 0, 0, kind=9))
put('artnet_timecode', 'bad-short.bin', art_timecode(0, 0, 0, 0)[:15])

# ---- OSC remote control ----
def osc_str(s):
    b = s.encode() + b'\0'
    return b + b'\0' * (-len(b) % 4)
def osc(address, *args):
    tags = ',' + ''.join('f' if isinstance(a, float) else 'i' if isinstance(a, int) else 's' for a in args)
    out = osc_str(address) + osc_str(tags)
    for a in args:
        out += struct.pack('>f', a) if isinstance(a, float) else struct.pack('>i', a) if isinstance(a, int) else osc_str(a)
    return out
put('osc', 'ok-go.bin', osc('/haze/go'))
put('osc', 'ok-cue.bin', osc('/haze/cue', '1.5'))
put('osc', 'ok-color.bin', osc('/haze/fixture/3/color', 1.0, 0.5, 0.0))
put('osc', 'ok-gobo.bin', osc('/haze/fixture/1/gobo', 'Stars'))
put('osc', 'bad-intensity-range.bin', osc('/haze/fixture/1/intensity', 2.0))
put('osc', 'bad-truncated.bin', osc('/haze/fixture/1/pan', 10.0)[:-2])
put('osc', 'bad-bundle.bin', b'#bundle\0' + b'\0' * 7 + b'\1' + struct.pack('>i', 12) + osc('/haze/go'))

# MIDI Time Code (MMA MTC spec): quarter frames F1 0n spelling 01:02:03:04 at 25 fps (pieces
# 0..7: frames 4|0, seconds 3|0, minutes 2|0, hours 1, hours-high 0 with rate 1 << 1), the
# same backwards, a Full Frame sysex; broken: a piece missing, minutes 60.
mtc_forward = bytes([0xF1, 0x04, 0xF1, 0x10, 0xF1, 0x23, 0xF1, 0x30, 0xF1, 0x42, 0xF1, 0x50, 0xF1, 0x61, 0xF1, 0x72])
put('midi_timecode', 'ok-quarter-frames.bin', mtc_forward)
put('midi_timecode', 'ok-backward.bin', b''.join(mtc_forward[i:i + 2] for i in range(14, -1, -2)))
put('midi_timecode', 'ok-full-frame.bin', bytes([0xF0, 0x7F, 0x7F, 0x01, 0x01, 0x21, 0x02, 0x03, 0x04, 0xF7]))
put('midi_timecode', 'bad-missing-piece.bin', mtc_forward[:4] + mtc_forward[6:])
put('midi_timecode', 'bad-minutes-60.bin', bytes([0xF0, 0x7F, 0x7F, 0x01, 0x01, 0x21, 0x3C, 0x03, 0x04, 0xF7]))

# ---- mesh (fixtures/mesh: GDTF body models, MVR geometry) ----
def chunk(cid, payload):
    return struct.pack('<HI', cid, 6 + len(payload)) + payload
def tds(vertices, faces, name=b'box'):
    verts = struct.pack('<H', len(vertices)) + b''.join(struct.pack('<fff', *v) for v in vertices)
    tris = struct.pack('<H', len(faces)) + b''.join(struct.pack('<HHHH', a, b, c, 0) for a, b, c in faces)
    mesh = chunk(0x4100, chunk(0x4110, verts) + chunk(0x4120, tris))
    obj = chunk(0x4000, name + b'\0' + mesh)
    return chunk(0x4D4D, chunk(0x0002, struct.pack('<I', 3)) + chunk(0x3D3D, obj))
cube_v = [(x, y, z) for x in (-50.0, 50.0) for y in (-50.0, 50.0) for z in (0.0, 100.0)]
cube_f = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
          (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
put('mesh', 'ok-cube.3ds', tds(cube_v, cube_f))
put('mesh', 'ok-triangle.glb', glb(doc, buf))
put('mesh', 'bad-no-faces.3ds', tds(cube_v, []))
put('mesh', 'bad-truncated.3ds', tds(cube_v, cube_f)[:40])
# A JSON chunk that declares 2.9 GB (found by the fuzzer: assimp allocated it before reading).
huge_chunk = bytearray(glb(doc, buf))
huge_chunk[12:16] = struct.pack('<I', 0xae000310)
put('mesh', 'bad-glb-chunk-length.glb', bytes(huge_chunk))

# ---- SVG gobo (fixtures/gobo_image.cpp through librsvg) ----
# QLC+'s form (a black disc with holes, a declared size and no viewBox), a viewBox-only one with
# a gradient and a group transform, an inline (data:) image; broken: cut short, not XML, a zero
# size, a sliver; an <image> referring to a file, which is not read (accepted: it draws nothing).
svg_head = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"'
svg_disc = (svg_head + ' width="80" height="80"><path fill-rule="evenodd" d="M40 0A40 40 0 0 0 0 40a40 40 0 0 0 '
            '40 40 40 40 0 0 0 40-40A40 40 0 0 0 40 0zm-7 7.363h14v65.274H33V7.363z"/></svg>\n')
put('svg_gobo', 'ok-qlc-disc.svg', svg_disc)
put('svg_gobo', 'ok-viewbox.svg', svg_head + ' viewBox="0 0 21.167 21.167"><defs><radialGradient id="g">'
    '<stop offset="0" stop-color="#fff"/><stop offset="1" stop-color="#000"/></radialGradient></defs>'
    '<g transform="rotate(30 10.5 10.5)"><circle cx="10.5" cy="10.5" r="10" fill="url(#g)"/>'
    '<rect x="4" y="9" width="13" height="3" fill="#000" opacity="0.5"/></g></svg>\n')
one_px_png = base64.b64encode(bytes.fromhex(
    '89504e470d0a1a0a0000000d49484452000000010000000108060000001f15c489'
    '0000000d49444154789c63f8ffffff7f0009fb03fd2a86e38a0000000049454e44ae426082')).decode()
put('svg_gobo', 'ok-inline-image.svg', svg_head + ' viewBox="0 0 10 10"><image width="10" height="10" '
    'xlink:href="data:image/png;base64,' + one_px_png + '"/></svg>\n')
put('svg_gobo', 'maybe-external-image.svg', svg_head + ' viewBox="0 0 10 10"><image width="10" height="10" '
    'xlink:href="/etc/hostname"/><use xlink:href="other.svg#x"/></svg>\n')
put('svg_gobo', 'bad-truncated.svg', svg_disc[:len(svg_disc) // 2])
put('svg_gobo', 'bad-not-xml.svg', 'GIF89a not an svg\n')
put('svg_gobo', 'bad-zero-size.svg', svg_head + ' width="0" height="80"/>\n')
put('svg_gobo', 'bad-sliver.svg', svg_head + ' width="100000" height="1"/>\n')

# ---- MVR-xchange TCP stream (shows/xchange, docs/mvr.md "MVR-xchange") ----
# The 28-byte header: magic 778682, version 1, packet number, packet count, type (0 JSON, 1 MVR
# file), uint64 payload length, all big-endian; then the payload. A stream holds several packets.
def xpacket(payload, kind=0, number=0, count=1, magic=778682, version=1, length=None):
    if isinstance(payload, (dict, list)):
        payload = json.dumps(payload)
    if isinstance(payload, str):
        payload = payload.encode('utf-8')
    n = len(payload) if length is None else length
    return struct.pack('>IIIIIQ', magic, version, number, count, kind, n) + payload
station = '4aa291a1-1a62-45fe-aabc-e90e5e2399a8'
mvr_file = 'a7669ff9-bd61-4486-aea6-c190f8ba6b8c'
x_join = {'Type': 'MVR_JOIN', 'Provider': 'Seed', 'StationName': 'Seed station', 'StationUUID': station,
          'verMajor': '1', 'verMinor': '6', 'Files': [{'FileUUID': mvr_file, 'FileSize': 64, 'verMajor': 1, 'verMinor': 6}]}
x_commit = {'Type': 'MVR_COMMIT', 'verMajor': 1, 'verMinor': 6, 'FileSize': 64, 'FileUUID': mvr_file,
            'StationUUID': station, 'ForStationsUUID': [], 'Comment': 'seed'}
x_mvr = zipped([('GeneralSceneDescription.xml', '<?xml version="1.0"?><GeneralSceneDescription verMajor="1" verMinor="6"/>')])
put('xchange', 'ok-join.bin', xpacket(x_join))
put('xchange', 'ok-commit-request-leave.bin', xpacket(x_commit) + xpacket({'Type': 'MVR_REQUEST', 'FileUUID': '', 'FromStationUUID': ''})
    + xpacket({'Type': 'MVR_LEAVE', 'FromStationUUID': station}))
put('xchange', 'ok-split-json.bin', xpacket('{"Type":"MVR_COMMIT_RET",', 0, 0, 2) + xpacket('"OK":"true","Message":""}', 0, 1, 2))
put('xchange', 'ok-file.bin', xpacket(x_mvr, 1))
put('xchange', 'bad-magic.bin', xpacket(x_join, magic=778683))
put('xchange', 'bad-version.bin', xpacket(x_join, version=2))
put('xchange', 'bad-type.bin', xpacket(x_join, kind=2))
put('xchange', 'bad-json-over-limit.bin', xpacket('{}', length=(1 << 20) + 1))
put('xchange', 'bad-truncated.bin', xpacket(x_join)[:-5])
put('xchange', 'bad-json-array.bin', xpacket(['MVR_JOIN']))
put('xchange', 'bad-join-missing-uuid.bin', xpacket({k: v for k, v in x_join.items() if k != 'StationUUID'}))
put('xchange', 'bad-file-not-zip.bin', xpacket(b'PK\x03\x04 not really a zip archive', 1))
