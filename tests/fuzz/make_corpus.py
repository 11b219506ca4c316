#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (tests/fuzz/corpus/<target>/). Run from anywhere;
rerun after editing. Seeds are small (a few KB at most): valid files of every variant the
readers accept, plus the known killers (Debian PCL 1.13, OpenCV 4.6), truncations, CRLF line
ends, NaN / Inf / 1e38, huge counts. Multi-file targets join their files with SEP."""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SEP = b"\n--part--\n"


def put(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def crlf(b):
    return b.replace(b"\n", b"\r\n") if isinstance(b, bytes) else b.replace("\n", "\r\n")


# ---------------------------------------------------------------- PCD
def pcd_head(n, data="ascii", fields="x y z", size="4 4 4", typ="F F F", count="1 1 1",
             width=None, height=1, viewpoint=True):
    w = n if width is None else width
    s = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
    s += f"FIELDS {fields}\nSIZE {size}\nTYPE {typ}\nCOUNT {count}\nWIDTH {w}\nHEIGHT {height}\n"
    if viewpoint:
        s += "VIEWPOINT 0 0 1.5 1 0 0 0\n"
    s += f"POINTS {n}\nDATA {data}\n"
    return s


pts = [(1.0, 2.0, 3.0), (4.0, 5.0, 6.0), (0.5, -1.5, 2.25), (7.0, 8.0, 9.0)]
ascii_body = "".join(f"{x} {y} {z}\n" for x, y, z in pts)
put("pcd", "ascii.pcd", pcd_head(4) + ascii_body)
put("pcd", "ascii_crlf.pcd", crlf(pcd_head(4) + ascii_body))
put("pcd", "ascii_nan_inf_1e38.pcd",
    pcd_head(5) + "nan nan nan\ninf 0 0\n1e38 1e38 1e38\n-1e999 2 3\n1 2 3\n")
put("pcd", "ascii_extra_fields.pcd",
    pcd_head(2, fields="x y z rgb normal", size="4 4 4 4 4", typ="F F F U F", count="1 1 1 1 3")
    + "1 2 3 255 0 0 1\n4 5 6 128 0 1 0\n")
put("pcd", "ascii_short_line.pcd", pcd_head(2) + "1 2 3\n4 5\n")
put("pcd", "ascii_truncated.pcd", pcd_head(4) + "1 2 3\n4 5 6\n")
bin_body = b"".join(struct.pack("<fff", *p) for p in pts)
put("pcd", "binary.pcd", pcd_head(4, "binary").encode() + bin_body)
put("pcd", "binary_truncated.pcd", pcd_head(4, "binary").encode() + bin_body[:20])
put("pcd", "binary_double_z_label.pcd",
    pcd_head(2, "binary", fields="x y z label", size="4 4 8 1", typ="F F F U", count="1 1 1 1").encode()
    + struct.pack("<ffdB", 1, 2, 3, 7) + struct.pack("<ffdB", float("nan"), 5, 6, 7))
# binary_compressed: fields stored one after another, LZF literal runs (control byte < 32).
soa = b"".join(struct.pack("<f", p[a]) for a in range(3) for p in pts)


def lzf_literal(raw):
    out = b""
    for i in range(0, len(raw), 32):
        chunk = raw[i:i + 32]
        out += bytes([len(chunk) - 1]) + chunk
    return out


comp = lzf_literal(soa)
put("pcd", "binary_compressed.pcd",
    pcd_head(4, "binary_compressed").encode() + struct.pack("<II", len(comp), len(soa)) + comp)
put("pcd", "binary_compressed_bad_sizes.pcd",
    pcd_head(4, "binary_compressed").encode() + struct.pack("<II", 9, len(soa)) + comp)
put("pcd", "binary_compressed_huge.pcd",
    pcd_head(4, "binary_compressed").encode() + struct.pack("<II", 0xFFFFFFFF, 0xFFFFFFF0) + comp[:8])
# binary_compressed_by_pcl.pcd (with LZF back-references) was written by
# pcl::io::savePCDFileBinaryCompressed from the same four points; it is kept as is.
# The Debian PCL 1.13 killers and relatives.
put("pcd", "empty.pcd", "")
put("pcd", "no_fields.pcd",
    "VERSION 0.7\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n")
put("pcd", "dims_65536_points_0.pcd", pcd_head(0, "binary", width=65536, height=65536))
put("pcd", "points_4e9_short_body.pcd", pcd_head(4000000000, "binary") + "abc")
put("pcd", "width_overflow.pcd", pcd_head(1, "binary", width=4294967296, height=4294967296).encode() + bin_body)
put("pcd", "huge_count.pcd", pcd_head(1, fields="x y z f", size="4 4 4 4", typ="F F F F",
                                      count="1 1 1 1048576") + "1 2 3 4\n")
put("pcd", "no_data_line.pcd", pcd_head(1).replace("DATA ascii\n", ""))
put("pcd", "header_only.pcd", pcd_head(1, "binary"))
put("pcd", "viewpoint_nan.pcd", pcd_head(1).replace("VIEWPOINT 0 0 1.5 1 0 0 0", "VIEWPOINT nan 0 0 1 0 0 0") + "1 2 3\n")
put("pcd", "duplicate_field.pcd", pcd_head(1, fields="x x z") + "1 2 3\n")
put("pcd", "columns_v05.pcd", pcd_head(1).replace("FIELDS", "COLUMNS") + "1 2 3\n")
put("pcd", "int_xyz.pcd", pcd_head(1, typ="I I I") + "1 2 3\n")

# ---------------------------------------------------------------- PLY
def ply_head(fmt, n, props=("float x", "float y", "float z"), extra=""):
    s = f"ply\nformat {fmt} 1.0\ncomment seed\nelement vertex {n}\n"
    s += "".join(f"property {p}\n" for p in props) + extra + "end_header\n"
    return s


put("ply", "ascii.ply", ply_head("ascii", 4) + ascii_body)
put("ply", "ascii_crlf.ply", crlf(ply_head("ascii", 4) + ascii_body))
put("ply", "ascii_nan_inf_1e38.ply", ply_head("ascii", 4) + "nan nan nan\ninf 0 0\n1e38 1e38 1e38\n1 2 3\n")
put("ply", "ascii_faces.ply",
    ply_head("ascii", 3, extra="element face 1\nproperty list uchar int vertex_indices\n")
    + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
put("ply", "ascii_truncated.ply", ply_head("ascii", 4) + "1 2 3\n4 5")
put("ply", "binary_le.ply", ply_head("binary_little_endian", 4).encode() + bin_body)
put("ply", "binary_be.ply", ply_head("binary_big_endian", 4).encode()
    + b"".join(struct.pack(">fff", *p) for p in pts))
put("ply", "binary_double_rgb.ply",
    ply_head("binary_little_endian", 2, props=("double x", "double y", "double z", "uchar red")).encode()
    + struct.pack("<dddB", 1, 2, 3, 9) + struct.pack("<dddB", 4, 5, 6, 9))
put("ply", "binary_elements_before.ply",
    ("ply\nformat binary_little_endian 1.0\nelement camera 1\nproperty list uchar float k\n"
     "element vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n").encode()
    + bytes([2]) + struct.pack("<ff", 1, 2) + bin_body[:24])
put("ply", "binary_truncated.ply", ply_head("binary_little_endian", 4).encode() + bin_body[:30])
put("ply", "vertex_4e9.ply", ply_head("binary_little_endian", 4000000000).encode() + bin_body)
put("ply", "vertex_0.ply", ply_head("ascii", 0))
put("ply", "empty.ply", "")
put("ply", "no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n")
put("ply", "list_huge_count.ply",
    ply_head("binary_little_endian", 1, extra="").replace("element vertex 1", "element face 1\nproperty list uint int idx\nelement vertex 1").encode()
    + struct.pack("<I", 0xFFFFFFFF) + bin_body[:12])

# ---------------------------------------------------------------- XYZ
put("xyz", "plain.xyz", ascii_body)
put("xyz", "crlf.xyz", crlf("# comment\n" + ascii_body))
put("xyz", "nan_inf_1e38.xyz", "nan nan nan\ninf -inf 0\n1e38 1e38 1e38\n1e999 0 0\n+1.5 -.5 2e-3\n1 2 3\n")
put("xyz", "csv_header.xyz", "x,y,z,intensity\n1,2,3,0.5\n4 , 5 , 6,0.7\n")
put("xyz", "extra_columns.xyz", "1 2 3 255 128 64 0.3\n4\t5\t6\t1\n")
put("xyz", "comments_blank.xyz", "// exported\n\n# x y z\n1 2 3\n\n")
put("xyz", "malformed.xyz", "1 2 3\n4 five 6\n")
put("xyz", "two_values.xyz", "1 2\n")
put("xyz", "empty.xyz", "")
put("xyz", "only_comments.xyz", "# nothing\n# here\n")
put("xyz", "no_final_newline.xyz", "1 2 3\n4 5 6")
put("xyz", "binary_junk.xyz", bytes(range(256)))

# ---------------------------------------------------------------- 3DTK
scan = "0 0 100 1 2 3 4 5\n100 50 200 0 0 0 0 0\n-50 20 300 0 0 0 0 0\n"
pose = "10 20 30\n0 90 0\n"
frames = ("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 2\n" * 2)
put("tdtk", "scan_only.bin", scan)
put("tdtk", "scan_pose.bin", (scan + SEP.decode() + pose))
put("tdtk", "two_scans_pose_frames.bin", SEP.join([scan.encode(), pose.encode(), scan.encode(), frames.encode()]))
put("tdtk", "crlf.bin", SEP.join([crlf(scan).encode(), crlf(pose).encode()]))
put("tdtk", "nan_inf_1e38.bin", "nan 0 0\ninf 1 1\n1e38 1e38 1e38\n1 2 3\n")
put("tdtk", "pose_bad.bin", scan + SEP.decode() + "10 20\n0 0 0\n")
put("tdtk", "pose_huge.bin", scan + SEP.decode() + "1e308 1e308 1e308\n1e300 0 0\n")
put("tdtk", "frames_short.bin", SEP.join([scan.encode(), b"", scan.encode(), b"1 0 0 1\n"]))
put("tdtk", "frames_16.bin", SEP.join([scan.encode(), b"", scan.encode(), b"1 0 0 0 0 1 0 0 0 0 1 0 5 5 5 1\n"]))
put("tdtk", "empty_scan.bin", "")
put("tdtk", "malformed_scan.bin", "1 2 3\nx y z\n")

# ---------------------------------------------------------------- LAS
LAS_REC = [20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67]  # minimum record bytes, formats 0-10
LAS_BLOCK = {2: 227, 3: 235, 4: 375}


def las(minor=2, fmt=0, pts=pts, scale=0.001, offset=(0.0, 0.0, 0.0), extra=0, vlrs=b"",
        vlr_count=None, legacy=True, wide=None, count=None, box=None, header_bytes=None,
        point_offset=None, fmt_byte=None):
    """A LAS file (the layout of lib/cloud_io/src/las_write.cpp, plus VLRs and lies)."""
    block = LAS_BLOCK[minor]
    rec = LAS_REC[fmt] + extra
    body = b""
    for p in pts:
        q = [int(round((p[a] - offset[a]) / scale)) for a in range(3)]
        r = bytearray(rec)
        r[0:12] = struct.pack("<iii", *q)
        r[14] = 0x11 if fmt >= 6 else 0x09
        body += bytes(r)
    n = len(pts) if count is None else count
    h = bytearray(block)
    h[0:4] = b"LASF"
    h[24], h[25] = 1, minor
    h[26:35] = b"indoormap"
    struct.pack_into("<H", h, 94, block if header_bytes is None else header_bytes)
    struct.pack_into("<I", h, 96, block + len(vlrs) if point_offset is None else point_offset)
    struct.pack_into("<I", h, 100, (len(vlrs) // 54 if vlrs else 0) if vlr_count is None else vlr_count)
    h[104] = fmt if fmt_byte is None else fmt_byte
    struct.pack_into("<H", h, 105, rec)
    if legacy:
        struct.pack_into("<II", h, 107, n & 0xFFFFFFFF, n & 0xFFFFFFFF)
    lo = [min(p[a] for p in pts) for a in range(3)] if pts else [0.0] * 3
    hi = [max(p[a] for p in pts) for a in range(3)] if pts else [0.0] * 3
    if box is not None:
        lo, hi = box
    struct.pack_into("<3d", h, 131, scale, scale, scale)
    struct.pack_into("<3d", h, 155, *offset)
    struct.pack_into("<6d", h, 179, hi[0], lo[0], hi[1], lo[1], hi[2], lo[2])
    if minor == 4:
        struct.pack_into("<QQ", h, 247, n if wide is None else wide, n)
    return bytes(h) + vlrs + body


def vlr(user=b"LASF_Projection", record_id=34735, payload=b"\x01\x00\x01\x00\x00\x00\x00\x00"):
    return (struct.pack("<H", 0) + user.ljust(16, b"\0") + struct.pack("<HH", record_id, len(payload))
            + b"description".ljust(32, b"\0") + payload)


for fmt in range(6):
    put("las", f"v12_format{fmt}.las", las(2, fmt))
put("las", "v13_format1.las", las(3, 1))
put("las", "v13_format4.las", las(3, 4))
for fmt in range(11):
    put("las", f"v14_format{fmt}.las", las(4, fmt, legacy=fmt <= 5))
put("las", "v14_wide_count_only.las", las(4, 1, legacy=False))
put("las", "v12_extra_bytes.las", las(2, 3, extra=7))
put("las", "v14_extra_bytes.las", las(4, 6, extra=13, legacy=False))
put("las", "v12_vlr.las", las(2, 0, vlrs=vlr()))
put("las", "v14_two_vlrs.las", las(4, 7, vlrs=vlr() + vlr(b"LASF_Spec", 4, b"x" * 20), legacy=False))
utm = [(500000.0 + x, 5000000.0 + y, 100.0 + z) for x, y, z in pts]
put("las", "utm_offset.las", las(2, 1, pts=utm, offset=(500000.0, 5000000.0, 0.0)))
put("las", "utm_box_lies.las", las(2, 1, pts=utm, offset=(0.0, 0.0, 0.0), scale=0.01,
                                  box=([1e300, -1e300, 0.0], [-1e300, 1e300, 0.0])))
put("las", "box_nan.las", las(2, 0, box=([float("nan")] * 3, [float("inf")] * 3)))
put("las", "scale_tiny.las", las(2, 0, pts=[(5e-300, 0.0, 1e-299)], scale=1e-300))
put("las", "zero_points.las", las(2, 0, pts=[]))
# broken
put("las", "empty.las", b"")
put("las", "signature_only.las", b"LASF")
put("las", "header_truncated.las", las(2, 0)[:200])
put("las", "v14_header_truncated.las", las(4, 0)[:300])
put("las", "version_1_5.las", las(2, 0)[:25] + b"\x05" + las(2, 0)[26:])
put("las", "points_truncated.las", las(2, 1)[:-10])
put("las", "count_lies.las", las(2, 0, count=1000000))
put("las", "v14_counts_disagree.las", las(4, 1, wide=7))
put("las", "v14_count_huge.las", las(4, 6, legacy=False, wide=2 ** 63))
put("las", "header_size_small.las", las(2, 0, header_bytes=100))
put("las", "point_offset_past_end.las", las(2, 0, point_offset=1 << 30))
put("las", "point_offset_in_header.las", las(2, 0, point_offset=10))
put("las", "format_11.las", las(2, 0, fmt_byte=11))
put("las", "laz_format_byte.las", las(2, 1, fmt_byte=0x81))
put("las", "laszip_vlr.las", las(2, 1, vlrs=vlr(b"laszip encoded", 22204, b"\0" * 34)))
put("las", "vlr_count_lies.las", las(2, 0, vlrs=vlr(), vlr_count=1000))
put("las", "vlr_length_lies.las", las(2, 0, vlrs=vlr()[:-8], point_offset=227 + 54))
put("las", "record_short.las", las(2, 3)[:105] + struct.pack("<H", 20) + las(2, 3)[107:])
put("las", "scale_zero.las", las(2, 0)[:131] + struct.pack("<d", 0.0) + las(2, 0)[139:])
put("las", "offset_nan.las", las(2, 0)[:155] + struct.pack("<d", float("nan")) + las(2, 0)[163:])


# ---------------------------------------------------------------- ROS map
def pgm(w, h, pixels=None, maxval=255):
    if pixels is None:
        pixels = bytes(((x * 37 + y * 11) % 3) * 100 + 5 for y in range(h) for x in range(w))
    return f"P5\n# seed\n{w} {h}\n{maxval}\n".encode() + pixels


def png(w, h, raw_rows, bit_depth=8, colour=0):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", w, h, bit_depth, colour, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw_rows)) + chunk(b"IEND", b"")


map_yaml = ("image: map.pgm\nmode: trinary\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
put("ros_map", "pgm.bin", map_yaml.encode() + SEP + pgm(8, 6))
put("ros_map", "pgm_crlf_yaml.bin", crlf(map_yaml).encode() + SEP + pgm(4, 4))
put("ros_map", "p2_ascii.bin", map_yaml.encode() + SEP + b"P2\n3 2\n255\n0 205 254\n254 0 205\n")
put("ros_map", "png.bin", map_yaml.replace("map.pgm", "map.png").encode() + SEP
    + png(4, 3, b"".join(b"\x00" + bytes([0, 205, 254, 100]) for _ in range(3))))
put("ros_map", "png_huge_ihdr.bin", map_yaml.encode() + SEP + png(65536, 65536, b"\x00\x00"))
put("ros_map", "pgm_huge_short.bin", map_yaml.encode() + SEP + b"P5\n100000 100000\n255\n\x00\x00")
put("ros_map", "pgm_65536_short.bin", map_yaml.encode() + SEP + b"P5\n65536 65536\n255\n\x00\x00")
put("ros_map", "pgm_16bit.bin", map_yaml.encode() + SEP + pgm(2, 2, b"\x00\x01\xff\xff\x80\x00\x00\x00", 65535))
put("ros_map", "pgm_truncated.bin", map_yaml.encode() + SEP + pgm(8, 6)[:-10])
put("ros_map", "image_empty.bin", map_yaml.encode() + SEP)
put("ros_map", "image_missing.bin", map_yaml.replace("map.pgm", "nothere.pgm").encode() + SEP + pgm(2, 2))
put("ros_map", "yaml_empty.bin", SEP + pgm(2, 2))
put("ros_map", "yaml_not_map.bin", b"- 1\n- 2\n" + SEP + pgm(2, 2))
put("ros_map", "resolution_zero.bin", map_yaml.replace("0.05", "0").encode() + SEP + pgm(2, 2))
put("ros_map", "negate_nan_1e38.bin", map_yaml.replace("negate: 0", "negate: .nan").replace("0.65", "1e38").encode() + SEP + pgm(2, 2))
put("ros_map", "negate_huge.bin", map_yaml.replace("negate: 0", "negate: 1e300").encode() + SEP + pgm(2, 2))
put("ros_map", "origin_bad.bin", map_yaml.replace("[-1.0, -2.0, 0.0]", "[1, .inf]").encode() + SEP + pgm(2, 2))
put("ros_map", "yaml_invalid.bin", b"image: [unclosed\nresolution: {\n" + SEP + pgm(2, 2))
put("ros_map", "image_is_dir.bin", map_yaml.replace("map.pgm", ".").encode() + SEP + pgm(2, 2))

# ---------------------------------------------------------------- config
with open(os.path.join(HERE, "..", "..", "config", "default.yaml"), "rb") as f:
    default_yaml = f.read()
put("config", "default.yaml", default_yaml)
put("config", "default_crlf.yaml", crlf(default_yaml))
put("config", "empty.yaml", "")
put("config", "typo.yaml", "voxel:\n  cel_m: 0.1\n")
put("config", "unknown_section.yaml", "voxels:\n  cell_m: 0.1\n")
put("config", "wrong_types.yaml", "level:\n  max_tilt_deg: steep\n  enabled: maybe\n")
put("config", "nan_inf_1e38.yaml", "voxel:\n  cell_m: .nan\n  bounds_gap_m: .inf\nlayers:\n  wall_band_m: 1e38\n")
put("config", "huge_ints.yaml", "input:\n  max_points: 1e30\nvoxel:\n  max_cells: -5\nlevel:\n  seed: 18446744073709551615\n")
put("config", "int_fraction.yaml", "level:\n  iterations: 2.5\n  sample_points: 1e19\n")
put("config", "scanners.yaml", "input:\n  scanners: [[0, 0, 1.5], [1, 2, 1.2]]\n  up_axis: y\n  unit_m: 0.01\n")
put("config", "scanners_bad.yaml", "input:\n  scanners: [[0, 0], 5]\n  up_axis: x\n")
put("config", "not_mapping.yaml", "- voxel\n- level\n")
put("config", "section_scalar.yaml", "voxel: 5\n")
put("config", "complex_key.yaml", "? [a, b]\n: 1\n")
put("config", "deep_nesting.yaml", "[" * 300 + "]" * 300 + "\n")
put("config", "anchors.yaml", "voxel: &v\n  cell_m: 0.1\nlayout: *v\n")
put("config", "optional_null.yaml", "layers:\n  floor_z_m: ~\n  ceiling_z_m: 2.5\n")

# ---------------------------------------------------------------- plain image map (plan-route)
# Byte 0: bits 0-1 the file name (map.pgm, map.png, map.PNG, map), bits 2-4 the resolution
# (0.05, 0.1, 1, 1e-9, 1e9, 0, -1, NaN); byte 1: --free-min. Then the image.
def plain(name_idx, res_idx, free_min, image):
    return bytes([name_idx | (res_idx << 2), free_min]) + image


png_rows = b"".join(b"\x00" + bytes([0, 205, 254, 100]) for _ in range(3))
put("plain_map", "pgm.bin", plain(0, 0, 250, pgm(8, 6)))
put("plain_map", "png.bin", plain(1, 0, 250, png(4, 3, png_rows)))
put("plain_map", "png_named_pgm.bin", plain(0, 1, 128, png(4, 3, png_rows)))
put("plain_map", "pgm_no_extension_free_min_0.bin", plain(3, 2, 0, pgm(3, 3)))
put("plain_map", "p2_ascii.bin", plain(2, 0, 255, b"P2\n3 2\n255\n0 205 254\n254 0 205\n"))
put("plain_map", "pgm_crlf_header.bin", plain(0, 0, 250, b"P5\r\n# c\r\n2 2\r\n255\r\n\x00\xfe\xcd\x00"))
put("plain_map", "pgm_16bit.bin", plain(0, 0, 250, pgm(2, 2, b"\x00\x01\xff\xff\x80\x00\x00\x00", 65535)))
put("plain_map", "pgm_maxval_0.bin", plain(0, 0, 250, pgm(2, 2, b"\x00\x01\x02\x03", 0)))
put("plain_map", "pgm_maxval_65536.bin", plain(0, 0, 250, pgm(2, 2, b"\x00" * 8, 65536)))
put("plain_map", "pgm_truncated.bin", plain(0, 0, 250, pgm(8, 6)[:-10]))
put("plain_map", "pgm_huge_short.bin", plain(0, 0, 250, b"P5\n100000 100000\n255\n\x00\x00"))
put("plain_map", "pgm_negative_size.bin", plain(0, 0, 250, b"P5\n-2 2\n255\n\x00\x00\x00\x00"))
put("plain_map", "png_16bit_rgb.bin", plain(1, 0, 200, png(2, 2, b"\x00" + b"\x12\x34" * 6 + b"\x00" + b"\xff\xff" * 6, 16, 2)))
put("plain_map", "png_huge_ihdr.bin", plain(1, 0, 250, png(65536, 65536, b"\x00\x00")))
put("plain_map", "png_width_zero.bin", plain(1, 0, 250, png(0, 5, b"\x00")))
put("plain_map", "png_corrupt_idat.bin", plain(1, 0, 250, png(4, 3, png_rows)[:45] + b"garbage"))
put("plain_map", "resolution_tiny_huge.bin", plain(0, 3, 250, pgm(2, 2)))
put("plain_map", "resolution_1e9.bin", plain(1, 4, 250, png(4, 3, png_rows)))
put("plain_map", "resolution_zero.bin", plain(0, 5, 250, pgm(2, 2)))
put("plain_map", "resolution_nan.bin", plain(0, 7, 250, pgm(2, 2)))
put("plain_map", "gif.bin", plain(0, 0, 250, b"GIF89a\x02\x00\x02\x00\x00\x00\x00;"))
put("plain_map", "empty.bin", b"")

# ---------------------------------------------------------------- planner config (plan-route -c)
with open(os.path.join(HERE, "..", "..", "config", "plan-route.yaml"), "rb") as f:
    plan_yaml = f.read()
put("plan_config", "plan-route.yaml", plan_yaml)
put("plan_config", "plan-route_crlf.yaml", crlf(plan_yaml))
put("plan_config", "empty.yaml", "")
put("plan_config", "typo.yaml", "robot:\n  widht_m: 0.5\n")
put("plan_config", "unknown_section.yaml", "planer:\n  d_max_m: 2\n")
put("plan_config", "wrong_types.yaml", "robot:\n  width_m: wide\nplanner:\n  paper_rules: maybe\n  max_routes: [1, 2]\n")
put("plan_config", "nan_inf_1e38.yaml", "robot:\n  width_m: .nan\n  length_m: .inf\n  extra_m: 1e38\nplanner:\n  d_max_m: 1e999\n")
put("plan_config", "int_inf.yaml", "planner:\n  max_nodes: .inf\n  extra_moves: -.inf\n")
put("plan_config", "huge_ints.yaml", "planner:\n  max_nodes: 9223372036854775808\n  max_routes: -5\n  extra_moves: 1e30\n")
put("plan_config", "int_fraction.yaml", "planner:\n  max_routes: 2.5\n  max_nodes: 1e5\n")
put("plan_config", "both_searches_off.yaml", "planner:\n  paper_rules: false\n  search: paper\n")
put("plan_config", "d_min_above_d_max.yaml", "planner:\n  d_min_m: 4\n  d_max_m: 3\n")
put("plan_config", "not_mapping.yaml", "- robot\n- planner\n")
put("plan_config", "section_scalar.yaml", "robot: 5\n")
put("plan_config", "section_null.yaml", "robot:\nplanner: ~\n")
put("plan_config", "complex_key.yaml", "robot:\n  ? [a, b]\n  : 1\n")
put("plan_config", "pipeline_section.yaml", "voxel:\n  cell_m: 0.1\n")
put("plan_config", "anchors.yaml", "robot: &r\n  width_m: 0.3\nplanner: *r\n")
put("plan_config", "deep_nesting.yaml", "robot: " + "[" * 300 + "]" * 300 + "\n")
put("plan_config", "yaml_invalid.yaml", "robot: {width_m: 0.4\nplanner: [\n")

# ---------------------------------------------------------------- layout PGM (map-eval)
def layout(w, h):
    return f"P5\n{w} {h}\n255\n".encode() + bytes((x + 2 * y) % 4 for y in range(h) for x in range(w))


put("layout_pgm", "layout.pgm", layout(6, 4))
put("layout_pgm", "layout_comment.pgm", b"P5\n# written by pcd-to-map\n3 2\n# maxval\n3\n\x00\x01\x02\x03\x00\x01")
put("layout_pgm", "layout_1x1.pgm", b"P5 1 1 255 \x02")
put("layout_pgm", "ros_map_values.pgm", pgm(4, 3))
put("layout_pgm", "crlf_header.pgm", b"P5\r\n3 2\r\n255\r\n\x00\x01\x02\x03\x00\x01")
put("layout_pgm", "truncated.pgm", layout(6, 4)[:-5])
put("layout_pgm", "huge_dims.pgm", b"P5 100000 100000 255\n\x00\x00")
put("layout_pgm", "huge_dims_in_range_short.pgm", b"P5\n100000 4000\n255\n\x00\x00")
put("layout_pgm", "maxval_0.pgm", b"P5\n2 2\n0\n\x00\x00\x00\x00")
put("layout_pgm", "maxval_65535.pgm", b"P5\n2 2\n65535\n" + b"\x00" * 8)
put("layout_pgm", "negative_size.pgm", b"P5\n-2 2\n255\n\x00\x00\x00\x00")
put("layout_pgm", "size_overflow.pgm", b"P5\n99999999999999999999 2\n255\n\x00")
put("layout_pgm", "p2_ascii.pgm", b"P2\n2 2\n3\n0 1\n2 3\n")
put("layout_pgm", "p5_no_space.pgm", b"P5x 2 2 255\n\x00\x00\x00\x00")
put("layout_pgm", "not_pgm.pgm", b"\x89PNG\r\n\x1a\n")
put("layout_pgm", "empty.pgm", b"")
