"""Shared helpers of the Python tests (run by ctest: tests/CMakeLists.txt sets the environment)."""
import os
import struct
import subprocess
import tempfile

import numpy as np

SOURCE_DIR = os.environ["INDOORMAP_SOURCE_DIR"]
BIN_DIR = os.environ["INDOORMAP_BIN_DIR"]
OFFICE = os.path.join(SOURCE_DIR, "clouds", "office", "cloud.pcd")


def run_app(app, *args):
    """Runs an app of the build; returns (exit code, stdout, stderr)."""
    p = subprocess.run([os.path.join(BIN_DIR, app), *args], capture_output=True, text=True,
                       timeout=600, check=False)
    return p.returncode, p.stdout, p.stderr


def scratch():
    return tempfile.mkdtemp(prefix="indoormap-py-")


def read_pgm(path):
    """A binary PGM (P5, 8 bit) as an array, row 0 = the image's top row."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; '#' comments skipped
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P5" and int(fields[3]) < 256, fields
    w, h = int(fields[1]), int(fields[2])
    return np.frombuffer(data[pos + 1:pos + 1 + w * h], dtype=np.uint8).reshape(h, w)


def problem(message):
    """An error message without its 'FILE[:LINE]: ' prefix (and an app's 'APP: ' prefix)."""
    for prefix in ("pcd-to-map: ",):
        if message.startswith(prefix):
            message = message[len(prefix):]
    head, sep, rest = message.partition(": ")
    if sep and (":" in head or "/" in head or head == "params"):
        return rest.strip()
    return message.strip()


def box_room(w=4.0, d=3.0, h=2.6, step=0.05, seed=1):
    """A box room w x d x h m (floor, ceiling, four walls) with a cabinet top at 0.9 m against
    the south wall (x 0.5-1.5, y 0.1-0.6), as an (N, 3) float32 array in metres, z up."""
    rng = np.random.default_rng(seed)
    xs, ys, zs = (np.arange(0.0, s + 1e-9, step) for s in (w, d, h))
    gx, gy = np.meshgrid(xs, ys)
    floor = np.column_stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)])
    ceiling = floor + [0.0, 0.0, h]
    wx, wz = np.meshgrid(xs, zs)
    south = np.column_stack([wx.ravel(), np.zeros(wx.size), wz.ravel()])
    north = south + [0.0, d, 0.0]
    wy, wz2 = np.meshgrid(ys, zs)
    west = np.column_stack([np.zeros(wy.size), wy.ravel(), wz2.ravel()])
    east = west + [w, 0.0, 0.0]
    cx, cy = np.meshgrid(np.arange(0.5, 1.5, step), np.arange(0.1, 0.6, step))
    cabinet = np.column_stack([cx.ravel(), cy.ravel(), np.full(cx.size, 0.9)])
    pts = np.vstack([floor, ceiling, south, north, west, east, cabinet])
    return (pts + rng.normal(0.0, 0.003, pts.shape)).astype(np.float32)


def write_las(path, points, offset, scale=0.001):
    """points (N, 3) in metres as a LAS 1.2 point format 0 file whose header offset is `offset`
    (source coordinates = offset + points, stored as int32 multiples of `scale`)."""
    q = np.round(np.asarray(points, dtype=np.float64) / scale).astype("<i4")
    src = q * scale + np.asarray(offset, dtype=np.float64)
    lo, hi = src.min(axis=0), src.max(axis=0)
    header = struct.pack("<4sHH16sBB32s32sHHHIIBHI5I3d3d6d", b"LASF", 0, 0, b"\0" * 16, 1, 2,
                         b"indoormap test", b"support.py", 1, 2026, 227, 227, 0, 0, 20, len(q),
                         len(q), 0, 0, 0, 0, scale, scale, scale, *offset,
                         hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
    assert len(header) == 227
    rec = np.zeros(len(q), dtype=[("xyz", "<i4", 3), ("intensity", "<u2"), ("flags", "u1"),
                                  ("cls", "u1"), ("angle", "i1"), ("user", "u1"),
                                  ("source", "<u2")])
    rec["xyz"], rec["flags"] = q, 0b00001001  # return 1 of 1
    with open(path, "wb") as f:
        f.write(header + rec.tobytes())
    return q * scale  # the local coordinates, as exact as the file holds them
