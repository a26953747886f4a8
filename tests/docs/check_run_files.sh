#!/usr/bin/env bash
# docs/run-files.md names every column of timeline.csv, faults.csv and ipu_commands.csv and every
# field of stats.json that a play writes (issue #33: the run files document their units; issue #30).
# Two plays: a sample with a fault plan and a
# branch, and a stream with P and B pictures whose first P picture is damaged.
#   check_run_files.sh VBIM SOURCE_DIR
set -euo pipefail
vbim="$1"
src="$2"
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-run-files.XXXXXX")
trap 'rm -rf "$work"' EXIT
"$vbim" play "$src/streams/samples/day_weather.vbim" --faults "$src/examples/fault-plans/stall.toml" \
  --branch 10s=1 --duration 30s --no-trace --trace-detail ipu --out "$work/a" >/dev/null
"$vbim" author --synthetic clear --synthetic-frames 12 --synthetic-size 64x64 --synthetic-sky-size 32x16 \
  --gop 6 --b-frames 2 --out "$work/gop.vbim" >/dev/null
python3 - "$work/gop.vbim" "$work/damaged.vbim" <<'PY'
import sys
d = bytearray(open(sys.argv[1], 'rb').read())
i = d.find(b'\x00\x00\x01\x00', 2048)
while (d[i + 5] >> 3) & 7 != 2:
    i = d.find(b'\x00\x00\x01\x00', i + 4)
d[i + 40] ^= 0xFF
open(sys.argv[2], 'wb').write(d)
PY
"$vbim" play "$work/damaged.vbim" --duration 20s --no-trace --trace-detail ipu --out "$work/b" >/dev/null
python3 - "$src/docs/run-files.md" "$work/a" "$work/b" <<'PY'
import json, re, sys
doc = open(sys.argv[1], encoding='utf-8').read()
named = set(re.findall(r'`([a-z0-9_.*]+)`', doc))
def documented(key):
    if key in named:
        return True
    # "`busy_share.drive`, `.sif`" names busy_share.sif; "frames.lightmap.*" rows name the last part
    parts = key.split('.')
    for i in range(len(parts) - 1, 0, -1):
        if '.' + '.'.join(parts[i:]) in named and any(n.startswith('.'.join(parts[:i]) + '.') for n in named):
            return True
    if parts[0] == 'frames' and len(parts) == 3 and parts[2] in named:
        return True
    if parts[0] in ('pop', 'lag') and ('%s.*.%s' % (parts[0], parts[2])) in named:
        return True
    return False
def flat(d, p=''):
    if isinstance(d, dict):
        for k, v in d.items():
            yield from flat(v, p + ('.' if p else '') + k)
    else:
        yield p
missing = []
for run in sys.argv[2:]:
    for key in flat(json.load(open(run + '/stats.json'))):
        if not documented(key):
            missing.append('stats.json ' + key)
    for name in ('timeline.csv', 'faults.csv', 'ipu_commands.csv'):
        header = open(run + '/' + name).readline().strip().split(',')
        missing += [name + ' ' + c for c in header if c not in named]
missing = sorted(set(missing))
if missing:
    print('docs/run-files.md does not document:\n  ' + '\n  '.join(missing))
    sys.exit(1)
print('docs/run-files.md documents every column and field of both runs')
PY
