# A station for tests/gui/mvr_xchange.sh, written from the MVR-xchange specification's text (TCP
# mode: the 28-byte big-endian header, JSON by hand): it joins haze announcing one file, and
# answers the REQUEST that haze's window sends with that file, then stays joined, answering
# commits, until haze leaves or closes (at most the socket's 120 s without a message).
# usage: python3 mvr_xchange_peer.py PORT FILE.mvr
import json, socket, struct, sys, uuid
port, mvr_path = int(sys.argv[1]), sys.argv[2]
mvr = open(mvr_path, 'rb').read()
fid = str(uuid.uuid4())
def packet(payload, kind=0):
    if isinstance(payload, dict): payload = json.dumps(payload).encode()
    return struct.pack('>IIIIIQ', 778682, 1, 0, 1, kind, len(payload)) + payload
def recv_exact(s, n):
    b = b''
    while len(b) < n:
        c = s.recv(n - len(b))
        if not c: raise SystemExit('closed')
        b += c
    return b
def read(s):
    h = struct.unpack('>IIIIIQ', recv_exact(s, 28))
    return h[4], recv_exact(s, h[5])
s = socket.create_connection(('127.0.0.1', port), timeout=120)
s.sendall(packet({'Type': 'MVR_JOIN', 'Provider': 'GuiTest', 'StationName': 'gui test station', 'StationUUID': str(uuid.uuid4()),
                  'verMajor': 1, 'verMinor': 6, 'Commits': [{'FileUUID': fid, 'FileSize': len(mvr), 'verMajor': 1, 'verMinor': 6, 'FileName': 'from gui test.mvr'}]}))
kind, body = read(s)
assert kind == 0 and json.loads(body)['Type'] == 'MVR_JOIN_RET', body
while True:
    kind, body = read(s)
    m = json.loads(body)
    if m['Type'] == 'MVR_REQUEST':
        assert m.get('FileUUID', '') in ('', fid), m
        s.sendall(packet(mvr, 1))
        break
# Joined until haze says MVR_LEAVE (the window's Stop) or closes: a loaded machine may take many
# seconds between the file and the Stop click.
try:
    while True:
        kind, body = read(s)
        m = json.loads(body) if kind == 0 else {}
        if m.get('Type') == 'MVR_COMMIT':
            s.sendall(packet({'Type': 'MVR_COMMIT_RET', 'OK': True, 'Message': ''}))
        elif m.get('Type') == 'MVR_LEAVE':
            s.sendall(packet({'Type': 'MVR_LEAVE_RET', 'OK': True, 'Message': ''}))
            break
except (SystemExit, OSError):
    pass
