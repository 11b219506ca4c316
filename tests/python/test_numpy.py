"""indoormap.run_pipeline on a hand-made numpy cloud: a 4 x 3 m box room with a cabinet."""
import unittest

import numpy as np

import indoormap
from support import box_room

W, D = 4.0, 3.0
SCANNER = (2.0, 1.5, 1.2)


class NumpyRoom(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.points = box_room(W, D)
        params = {"input": {"scanners": [list(SCANNER)]}, "voxel": {"cell_m": 0.05}}
        cls.r = indoormap.run_pipeline(cls.points, params, quiet=True)

    def cell_of(self, x, y):
        g = self.r["geometry"]
        return (int(np.floor((y - g["origin_m"][1]) / g["cell_m"])),
                int(np.floor((x - g["origin_m"][0]) / g["cell_m"])))

    def test_grids_have_the_geometry_and_the_room(self):
        g, layout, nav = self.r["geometry"], self.r["layout"], self.r["map"]
        self.assertEqual(g["cell_m"], 0.05)
        self.assertEqual(layout.shape, (g["height"], g["width"]))
        self.assertEqual(nav.shape, layout.shape)
        self.assertEqual(layout.dtype, np.uint8)
        self.assertEqual(nav.dtype, np.int8)
        # The grid spans the points: its extent covers the box, within a few cells.
        self.assertLessEqual(g["origin_m"][0], 0.0)
        self.assertGreaterEqual(g["origin_m"][0] + g["width"] * g["cell_m"], W)
        cells = indoormap.CELLS
        # The scanner's cell is free in both; the west wall at mid height is a wall / occupied.
        r, c = self.cell_of(SCANNER[0], SCANNER[1])
        self.assertEqual(layout[r, c], cells["free"])
        self.assertEqual(nav[r, c], 0)
        r, c = self.cell_of(0.0, D / 2)
        self.assertEqual(layout[r, c], cells["wall"])
        self.assertEqual(nav[r, c], 100)
        # Row 0 is the lowest y: the south wall (y = 0) is in the first rows, not the last.
        rows = np.nonzero(layout[:, self.cell_of(W / 2, 0)[1]] == cells["wall"])[0]
        self.assertLess(rows.min(), 3)
        self.assertTrue(set(np.unique(nav)) <= {-1, 0, 100})
        # The cabinet (0.9 m, against the south wall) is furniture in the layout.
        r, c = self.cell_of(1.0, 0.35)
        self.assertEqual(layout[r, c], cells["furniture"])

    def test_room_polygon_is_the_box(self):
        room = self.r["room"]
        self.assertTrue(room["closed"], room["reason"])
        poly = room["polygon_m"]
        self.assertEqual(poly.ndim, 2)
        self.assertEqual(poly.shape[1], 2)
        x, y = poly[:, 0], poly[:, 1]
        shoelace = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
        self.assertAlmostEqual(shoelace, room["area_m2"], places=6)
        self.assertLess(abs(room["area_m2"] - W * D), 0.1 * W * D)
        self.assertGreaterEqual(x.min(), -0.2)
        self.assertLessEqual(x.max(), W + 0.2)

    def test_objects_and_rooms(self):
        objs = self.r["objects"]
        self.assertGreaterEqual(len(objs), 1)
        cabinet = [o for o in objs if o["bbox_m"]["min"][0] < 1.0 < o["bbox_m"]["max"][0]
                   and o["bbox_m"]["min"][1] < 0.35 < o["bbox_m"]["max"][1]]
        self.assertEqual(len(cabinet), 1, objs)
        self.assertIn("kind", cabinet[0])
        self.assertEqual(len(self.r["rooms"]), 1)
        room = self.r["rooms"][0]
        self.assertEqual(room["polygon_m"].shape[1], 2)
        self.assertEqual(cabinet[0]["room_id"], room["id"])
        np.testing.assert_allclose(self.r["scanners_m"][0][:2], SCANNER[:2], atol=0.05)
        self.assertEqual(self.r["storeys"][0]["index"], 0)
        self.assertEqual(self.r["more_storeys"], [])

    def test_non_finite_points_dropped_and_counted(self):
        pts = self.points.copy()
        pts[::1000] = np.nan
        r = indoormap.run_pipeline(pts, {"input": {"scanners": [list(SCANNER)]},
                                         "voxel": {"cell_m": 0.05}}, quiet=True)
        inputs = r["summary"]["inputs"]
        self.assertEqual(inputs[0]["points_dropped"], len(pts[::1000]))
        self.assertEqual(inputs[0]["format"], "numpy")
        self.assertEqual(r["summary"]["points"]["kept"], len(pts) - len(pts[::1000]))
        # float64 input gives the same map as float32.
        r64 = indoormap.run_pipeline(self.points.astype(np.float64),
                                     {"input": {"scanners": [list(SCANNER)]},
                                      "voxel": {"cell_m": 0.05}}, quiet=True)
        np.testing.assert_array_equal(r64["map"], self.r["map"])


if __name__ == "__main__":
    unittest.main()
