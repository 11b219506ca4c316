"""indoormap.run_pipeline on a hand-made numpy cloud: a 4 x 3 m box room with a cabinet."""
import os
import unittest

import numpy as np

import indoormap
from support import box_room, scratch, write_las

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

    def test_align_walls_param_turns_a_rotated_room_onto_the_axes(self):
        turn = np.radians(12.0)
        rz = np.array([[np.cos(turn), -np.sin(turn), 0.0], [np.sin(turn), np.cos(turn), 0.0],
                       [0.0, 0.0, 1.0]])
        pts = (box_room(6.0, 4.0).astype(np.float64) @ rz.T).astype(np.float32)
        params = {"input": {"scanners": [(rz @ [3.0, 2.0, 1.2]).tolist()]},
                  "voxel": {"cell_m": 0.05}}
        plain = indoormap.run_pipeline(pts, params, quiet=True)
        params["align_walls"] = {"enabled": True}
        aligned = indoormap.run_pipeline(pts, params, quiet=True)

        def worst_edge_deg(poly):  # the largest angle of an edge off the nearest axis
            d = np.roll(poly, -1, axis=0) - poly
            a = np.degrees(np.arctan2(d[:, 1], d[:, 0])) % 90.0
            return np.max(np.minimum(a, 90.0 - a))

        self.assertTrue(aligned["room"]["closed"], aligned["room"]["reason"])
        self.assertLess(worst_edge_deg(aligned["room"]["polygon_m"]), 1.0)
        self.assertGreater(worst_edge_deg(plain["room"]["polygon_m"]), 10.0)
        # map_from_input undoes the turn: R = rz^T, within the levelling's tilt.
        np.testing.assert_allclose(aligned["summary"]["levelling"]["map_from_input"], rz.T,
                                   atol=0.01)
        self.assertLess(abs(aligned["room"]["area_m2"] - 24.0), 2.4)

    def test_las_loads_into_its_local_frame_with_the_offset(self):
        path = os.path.join(scratch(), "room.las")
        offset = (500000.0, 5000000.0, 100.0)  # georeferenced: UTM-like
        local = write_las(path, self.points, offset)
        d = indoormap.load_cloud(path)
        self.assertEqual(d["format"], "las")
        self.assertEqual(d["source_offset"], offset)
        self.assertEqual(d["inputs"][0]["source_offset"], offset)
        np.testing.assert_allclose(d["points"], local, atol=1e-6)
        self.assertEqual(d["scanners"].shape, (0, 3))  # LAS has no scanner position
        # Mapped as the numpy array of the same local points (given the same scanner).
        params = {"input": {"scanners": [list(SCANNER)]}, "voxel": {"cell_m": 0.05}}
        r = indoormap.run_pipeline(path, params, quiet=True)
        np.testing.assert_array_equal(r["map"], indoormap.run_pipeline(
            local.astype(np.float32), params, quiet=True)["map"])
        self.assertEqual(r["summary"]["inputs"][0]["source_offset"], list(offset))


if __name__ == "__main__":
    unittest.main()
