# An MVR-xchange station written for the test from the specification's text (MVR 1.6, DIN SPEC
# 15801, "MVR-xchange", TCP mode), not from haze's code: the 28-byte big-endian header (magic
# 778682, version 1, packet number, packet count, type 0 JSON / 1 MVR file, uint64 length) and
# the JSON messages built by hand. It talks to a running `haze live --mvr-xchange` and checks
# every answer; hostile packets must close the connection.
# usage: python3 mvr_xchange_station.py PORT SHOW HAZE_LOG ACCEPT_DIR
import hashlib, io, json, os, socket, struct, sys, time, uuid, zipfile

PORT, SHOW, LOG, ACCEPT = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
ME = str(uuid.uuid4())
HOST = '127.0.0.1'


def fail(msg):
    print('FAIL: ' + msg)
    sys.exit(1)


def packet(payload, kind=0, number=0, count=1, magic=778682, version=1, length=None):
    if isinstance(payload, dict):
        payload = json.dumps(payload).encode('utf-8')
    n = len(payload) if length is None else length
    return struct.pack('>IIIIIQ', magic, version, number, count, kind, n) + payload


def recv_exact(s, n):
    data = b''
    while len(data) < n:
        chunk = s.recv(min(1 << 20, n - len(data)))
        if not chunk:
            fail('haze closed the connection after %d of %d bytes' % (len(data), n))
        data += chunk
    return data


def read_packet(s):
    magic, version, number, count, kind, n = struct.unpack('>IIIIIQ', recv_exact(s, 28))
    if (magic, version, number, count) != (778682, 1, 0, 1):
        fail('header %r is not magic 778682, version 1, packet 0 of 1' % ((magic, version, number, count),))
    body = recv_exact(s, n)
    return kind, (json.loads(body) if kind == 0 else body)


def read_json(s, want):
    kind, msg = read_packet(s)
    if kind != 0 or msg.get('Type') != want:
        fail('expected %s, got %s' % (want, msg if kind == 0 else 'a file of %d bytes' % len(msg)))
    return msg


def connect():
    s = socket.create_connection((HOST, PORT), timeout=20)
    s.settimeout(20)
    return s


def wait_log(pattern, what):
    for _ in range(300):
        with open(LOG, encoding='utf-8', errors='replace') as f:
            if pattern in f.read():
                return
        time.sleep(0.1)
    fail('haze did not log "%s" (%s) within 30 s' % (pattern, what))


def closed_by_haze(s):
    try:
        return s.recv(1) == b''
    except (ConnectionResetError, socket.timeout):
        return False


def sha(b):
    return hashlib.sha256(b).hexdigest()


def accepted_files():
    return sorted(os.listdir(ACCEPT))


# 1. JOIN: haze answers with its uuid and the show it offers.
s = connect()
s.sendall(packet({'Type': 'MVR_JOIN', 'Provider': 'TestStation', 'StationName': 'test station', 'StationUUID': ME,
                  'verMajor': 1, 'verMinor': 6, 'Commits': []}))
ret = read_json(s, 'MVR_JOIN_RET')
if ret.get('OK') is not True or ret.get('Provider') != 'haze' or not ret.get('StationUUID'):
    fail('MVR_JOIN_RET is not OK from haze: %s' % ret)
files = ret.get('Commits')
if not isinstance(files, list) or len(files) != 1 or not files[0].get('FileUUID') or not files[0].get('FileSize'):
    fail('MVR_JOIN_RET lists %r; expected the one exported show' % files)
print('ok: MVR_JOIN_RET from %s offers file %s (%d bytes)' % (ret['StationName'], files[0]['FileUUID'], files[0]['FileSize']))

# 2. REQUEST it: the answer is a file packet of the announced size holding an MVR.
s.sendall(packet({'Type': 'MVR_REQUEST', 'FileUUID': files[0]['FileUUID'], 'FromStationUUID': ret['StationUUID']}))
kind, mvr = read_packet(s)
if kind != 1 or len(mvr) != files[0]['FileSize']:
    fail('MVR_REQUEST answered with type %d, %d bytes; expected an MVR file of %d' % (kind, len(mvr), files[0]['FileSize']))
names = zipfile.ZipFile(io.BytesIO(mvr)).namelist()
if 'GeneralSceneDescription.xml' not in names:
    fail('the file haze sent is no MVR: %s' % names)
print('ok: MVR_REQUEST gave %d bytes, a zip with %d entries' % (len(mvr), len(names)))
s.sendall(packet({'Type': 'MVR_REQUEST', 'FileUUID': str(uuid.uuid4()), 'FromStationUUID': ret['StationUUID']}))
miss = read_json(s, 'MVR_REQUEST_RET')
if miss.get('OK') is not False:
    fail('a request for an unknown file was not refused: %s' % miss)

# 3. A save of the show on disk becomes a COMMIT to the stations that joined.
with open(SHOW, 'a') as f:
    f.write('\n')
commit = read_json(s, 'MVR_COMMIT')
if commit.get('StationUUID') != ret['StationUUID'] or commit.get('FileUUID') == files[0]['FileUUID'] or commit.get('FileSize', 0) <= 0:
    fail('the commit after the save is not a new file of haze: %s' % commit)
s.sendall(packet({'Type': 'MVR_COMMIT_RET', 'OK': True, 'Message': ''}))
print('ok: saving the show sent MVR_COMMIT %s (%d bytes)' % (commit['FileUUID'], commit['FileSize']))


# 4. This station commits a file: haze requests it on the same connection and imports it.
def commit_and_serve(s, body, announced=None, send_len=None, send=None, close_after=False):
    fid = str(uuid.uuid4())
    s.sendall(packet({'Type': 'MVR_COMMIT', 'verMajor': 1, 'verMinor': 6, 'FileSize': announced or len(body),
                      'FileUUID': fid, 'StationUUID': ME, 'ForStationsUUID': [], 'Comment': 'from the test',
                      'FileName': 'from test.mvr'}))
    r = read_json(s, 'MVR_COMMIT_RET')
    if r.get('OK') is not True:
        fail('MVR_COMMIT not OK: %s' % r)
    req = read_json(s, 'MVR_REQUEST')
    if req.get('FileUUID') != fid:
        fail('haze requested %s; expected the committed %s' % (req.get('FileUUID'), fid))
    s.sendall(packet(send if send is not None else body, kind=1, length=send_len))
    if close_after:
        s.close()
    return fid

before = accepted_files()
fid = commit_and_serve(s, mvr)
wait_log('imported file ' + fid, 'the committed file imported')
after = accepted_files()
source = [n for n in after if n.endswith('_source.mvr') and n not in before]
shows = [n for n in after if n.endswith('.haze.json') and n not in before]
if len(source) != 1 or len(shows) != 1:
    fail('--accept-commits DIR holds %s; expected one new show and its source MVR' % after)
with open(os.path.join(ACCEPT, source[0]), 'rb') as f:
    got = f.read()
if sha(got) != sha(mvr):
    fail('the imported source %s (sha256 %s) differs from the file sent (%s)' % (source[0], sha(got), sha(mvr)))
print('ok: the committed file was requested, arrived byte for byte (sha256 %s...) and was imported as %s' % (sha(mvr)[:16], shows[0]))
print('SHOW ' + os.path.join(ACCEPT, shows[0]))

# 5. LEAVE.
s.sendall(packet({'Type': 'MVR_LEAVE', 'FromStationUUID': ME}))
if read_json(s, 'MVR_LEAVE_RET').get('OK') is not True:
    fail('MVR_LEAVE_RET not OK')
s.close()
print('ok: MVR_LEAVE answered')

# 6. Hostile input: one line in haze's log each, the connection closed, nothing written.
hostile = [
    ('not an MVR-xchange packet: header 778683', packet({'Type': 'MVR_JOIN'}, magic=778683)),
    ('version 7 is not supported', packet({'Type': 'MVR_JOIN'}, version=7)),
    ('unknown MVR-xchange packet type 9', packet({'Type': 'MVR_JOIN'}, kind=9)),
    ('over the limit of 1 MiB', packet(b'{}', length=(1 << 20) + 1)),
    ('over the limit of 256 MiB', packet(b'PK', kind=1, length=(256 << 20) + 1)),
    ('the JSON message is not an object', packet(b'["MVR_JOIN"]')),
    ("'StationUUID' is missing in MVR_JOIN", packet({'Type': 'MVR_JOIN', 'Provider': 'x', 'StationName': 'x'})),
    ('an MVR file came that haze did not request', packet(mvr, kind=1)),
]
for words, data in hostile:
    h = connect()
    h.sendall(data)
    if not closed_by_haze(h):
        fail('haze kept the connection open after: %s' % words)
    h.close()
    wait_log(words, 'a hostile packet')
print('ok: %d hostile packets: each logged and its connection closed' % len(hostile))

before = accepted_files()
t = connect()
t.sendall(packet({'Type': 'MVR_JOIN', 'Provider': 'T', 'StationName': 't', 'StationUUID': ME, 'Commits': []}))
read_json(t, 'MVR_JOIN_RET')
fid = commit_and_serve(t, mvr, send=mvr[:len(mvr) // 2], send_len=len(mvr), close_after=True)
wait_log('truncated packet: the stream ended after %d of %d payload bytes' % (len(mvr) // 2, len(mvr)), 'a cut transfer')
t = connect()
junk = b'\0' * len(mvr)
fid = commit_and_serve(t, junk)
if not closed_by_haze(t):
    fail('haze kept the connection open after a file that is not an MVR')
wait_log('MVR file ' + fid, 'a file that is no zip')
time.sleep(0.3)
if accepted_files() != before:
    fail('a cut or broken transfer wrote into DIR: %s' % sorted(set(accepted_files()) - set(before)))
print('ok: a cut transfer and a file that is no MVR wrote nothing')
