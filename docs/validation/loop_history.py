#!/usr/bin/env python3
"""Loop height (highest midsurface z, cm) of every converged step of one stage,
read from a result folder's states.bin (docs/format.md 5.2).

usage: loop_history.py RESULT_DIR [STAGE] [LAMBDA]
prints each step's lambda and loop height; with LAMBDA, the height
interpolated linearly at that lambda on the first pass of the stage.
"""
import struct
import sys
from pathlib import Path


def records(path):
    data = Path(path).read_bytes()
    assert data[:8] == b"DRAPESTA"
    version, n, e, _ = struct.unpack_from("<4I", data, 8)
    off = 24 + 24 * n + 16 * e + (4 if e % 2 else 0)
    size = 16 + 48 * n
    while off + size <= len(data):
        stage, step = struct.unpack_from("<2i", data, off)
        (lam,) = struct.unpack_from("<d", data, off + 8)
        z = struct.unpack_from("<%dd" % (3 * n), data, off + 16)[2::3]
        yield stage, step, lam, 100 * max(z)
        off += size


def main():
    folder = Path(sys.argv[1])
    stage = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    at = float(sys.argv[3]) if len(sys.argv) > 3 else None
    rows = [(s, lam, h) for st, s, lam, h in records(folder / "states.bin") if st == stage]
    if at is None:
        for s, lam, h in rows:
            print(f"{s:6d} {lam:9.5f} {h:8.3f}")
        return
    for (s0, l0, h0), (s1, l1, h1) in zip(rows, rows[1:]):
        if l1 < l0:
            break
        if l0 <= at <= l1:
            print(f"{folder}: loop height {h0 + (h1 - h0) * (at - l0) / (l1 - l0):.3f} cm at lambda {at} "
                  f"(steps {s0}-{s1}); highest lambda of the first pass {max(r[1] for r in rows):.4f}")
            return
    print(f"{folder}: lambda {at} not reached on the first pass")


if __name__ == "__main__":
    main()
