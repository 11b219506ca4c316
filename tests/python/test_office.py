"""indoormap on clouds/office: load_cloud gives the PCD's points and viewpoint; run_pipeline gives
what pcd-to-map writes for the same cloud (map.pgm, layout.pgm, map.yaml, objects.json,
room.geojson, rooms.geojson), so the bindings run the app's pipeline, not a copy of it."""
import json
import os
import re
import unittest

import numpy as np

import indoormap
from support import OFFICE, read_pgm, run_app, scratch


def pcd_header(path):
    header = {}
    with open(path, "rb") as f:
        for raw in f:
            line = raw.decode("ascii", "replace").strip()
            key, _, value = line.partition(" ")
            header[key] = value
            if key == "DATA":
                break
    return header


class LoadOffice(unittest.TestCase):
    def test_points_and_viewpoint_as_in_the_file(self):
        d = indoormap.load_cloud(OFFICE)
        header = pcd_header(OFFICE)
        self.assertEqual(d["points"].dtype, np.float32)
        self.assertEqual(d["points"].shape, (int(header["POINTS"]), 3))
        self.assertEqual(d["format"], "pcd")
        self.assertIsNone(d["source_offset"])  # only LAS inputs are moved
        self.assertEqual(d["inputs"][0]["points_read"], int(header["POINTS"]))
        view = [float(v) for v in header["VIEWPOINT"].split()[:3]]
        np.testing.assert_allclose(d["scanners"], [view], atol=1e-6)
        # The same points as the binary data section (float32 x y z, no conversion for metres).
        with open(OFFICE, "rb") as f:
            data = f.read()
        start = data.index(b"DATA binary\n") + len(b"DATA binary\n")
        raw = np.frombuffer(data[start:start + d["points"].nbytes], dtype="<f4").reshape(-1, 3)
        np.testing.assert_array_equal(d["points"], raw)

    def test_unit_param_scales(self):
        d = indoormap.load_cloud(OFFICE, {"input": {"unit_m": 0.5}})
        ref = indoormap.load_cloud(OFFICE)
        np.testing.assert_allclose(d["points"], ref["points"] * 0.5, rtol=1e-6)


class RunOffice(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = os.path.join(scratch(), "office")
        code, _, err = run_app("pcd-to-map", OFFICE, "-o", cls.out, "-q")
        assert code == 0, err
        cls.r = indoormap.run_pipeline(OFFICE, quiet=True)

    def file(self, name):
        return os.path.join(self.out, name)

    def test_grids_equal_the_apps_files(self):
        layout = read_pgm(self.file("layout.pgm"))[::-1]  # PGM row 0 is the top (highest y)
        np.testing.assert_array_equal(self.r["layout"], layout)
        ros = read_pgm(self.file("map.pgm"))[::-1]
        expected = np.select([ros == 254, ros == 0, ros == 205], [0, 100, -1], 99)
        np.testing.assert_array_equal(self.r["map"], expected.astype(np.int8))
        with open(self.file("map.yaml"), encoding="utf-8") as f:
            text = f.read()
        res = float(re.search(r"resolution:\s*([-0-9.e]+)", text).group(1))
        origin = [float(v) for v in re.search(r"origin:\s*\[([^\]]*)\]", text).group(1).split(",")]
        g = self.r["geometry"]
        self.assertAlmostEqual(g["cell_m"], res, places=9)
        np.testing.assert_allclose(g["origin_m"], origin[:2], atol=1e-6)

    def test_objects_equal_objects_json(self):
        with open(self.file("objects.json"), encoding="utf-8") as f:
            self.assertEqual(self.r["objects"], json.load(f)["objects"])

    def test_room_and_rooms_equal_the_geojson(self):
        with open(self.file("room.geojson"), encoding="utf-8") as f:
            feats = [x for x in json.load(f)["features"] if x["properties"].get("kind") == "room"]
        self.assertEqual(len(feats), 1 if self.r["room"]["closed"] else 0)
        if feats:
            ring = np.array(feats[0]["geometry"]["coordinates"][0])
            np.testing.assert_allclose(self.r["room"]["polygon_m"], ring[:-1], atol=1e-9)
        with open(self.file("rooms.geojson"), encoding="utf-8") as f:
            rooms = [x for x in json.load(f)["features"] if x["properties"].get("kind") == "room"]
        self.assertEqual(len(self.r["rooms"]), len(rooms))
        for got, feat in zip(self.r["rooms"], rooms):
            self.assertEqual(got["id"], feat["properties"]["id"])
            ring = np.array(feat["geometry"]["coordinates"][0])
            np.testing.assert_allclose(got["polygon_m"], ring[:-1], atol=1e-9)

    def test_summary_as_the_apps(self):
        with open(self.file("summary.json"), encoding="utf-8") as f:
            app = json.load(f)
        s = self.r["summary"]
        for key in ("points", "grid", "floor_z_m", "ceiling_z_m", "layout_cells", "parameters"):
            self.assertEqual(s[key], app[key], key)
        self.assertEqual(self.r["warnings"], app["warnings"])


if __name__ == "__main__":
    unittest.main()
