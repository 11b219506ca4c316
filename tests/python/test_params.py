"""indoormap.run_pipeline / load_cloud: the params dict is read by the apps' config reader (the
same keys, the same messages) and bad input raises ValueError naming the file."""
import os
import unittest

import numpy as np

import indoormap
from support import OFFICE, box_room, problem, run_app, scratch


def app_config_error(yaml_text):
    """pcd-to-map's message for a config file holding yaml_text (exit 2)."""
    path = os.path.join(scratch(), "bad.yaml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(yaml_text)
    code, _, err = run_app("pcd-to-map", "-c", path, OFFICE, "-o", os.path.join(scratch(), "o"))
    assert code == 2, (code, err)
    return err.strip()


class Params(unittest.TestCase):
    def assert_same_error_as_app(self, params, yaml_text):
        with self.assertRaises(ValueError) as ctx:
            indoormap.run_pipeline(box_room(), params)
        message = str(ctx.exception)
        self.assertTrue(message.startswith("params: ") or "invalid parameter" in message, message)
        self.assertEqual(problem(message), problem(app_config_error(yaml_text)))

    def test_unknown_key_refused_with_the_apps_message(self):
        self.assert_same_error_as_app({"voxel": {"cel_m": 0.05}}, "voxel:\n  cel_m: 0.05\n")

    def test_unknown_section_refused_with_the_apps_message(self):
        self.assert_same_error_as_app({"voxels": {"cell_m": 0.05}}, "voxels:\n  cell_m: 0.05\n")

    def test_wrong_type_refused_with_the_apps_message(self):
        self.assert_same_error_as_app({"voxel": {"cell_m": "abc"}}, "voxel:\n  cell_m: abc\n")
        self.assert_same_error_as_app({"objects": {"connectivity": 6}},
                                      "objects:\n  connectivity: 6\n")

    def test_out_of_range_refused_with_the_apps_message(self):
        self.assert_same_error_as_app({"voxel": {"cell_m": -1}}, "voxel:\n  cell_m: -1\n")

    def test_values_python_cannot_say_in_yaml(self):
        for params, expected in [
            ({"voxel": {"cell_m": object()}}, "key 'voxel.cell_m': cannot take a value of type"),
            ({"voxel": {1: 0.05}}, "keys must be strings"),
            ([("voxel", {})], "expected a dict of sections"),
        ]:
            with self.assertRaises(ValueError) as ctx:
                indoormap.run_pipeline(box_room(), params)
            self.assertIn(expected, str(ctx.exception))
            self.assertTrue(str(ctx.exception).startswith("params: "), str(ctx.exception))

    def test_default_params_are_the_apps_defaults_and_read_back(self):
        defaults = indoormap.default_params()
        self.assertIn("cell_m", defaults["voxel"])
        # numpy scalars and tuples are taken by value; the defaults read back unchanged.
        defaults["voxel"]["cell_m"] = np.float64(defaults["voxel"]["cell_m"])
        defaults["input"]["scanners"] = [(2.0, 1.5, 1.2)]
        r = indoormap.run_pipeline(box_room(), defaults, quiet=True)
        params = r["summary"]["parameters"]
        self.assertEqual(params["input"]["scanners"], [[2.0, 1.5, 1.2]])
        params["input"]["scanners"] = []
        self.assertEqual(params, indoormap.default_params())


class BadInput(unittest.TestCase):
    def test_missing_file_named(self):
        missing = os.path.join(scratch(), "nothere.pcd")
        for call in (indoormap.load_cloud, indoormap.run_pipeline):
            with self.assertRaises(ValueError) as ctx:
                call(missing)
            self.assertIn(missing, str(ctx.exception))

    def test_truncated_pcd_named(self):
        path = os.path.join(scratch(), "cut.pcd")
        with open(OFFICE, "rb") as f, open(path, "wb") as g:
            g.write(f.read(40000))
        code, _, err = run_app("pcd-to-map", path, "-o", os.path.join(scratch(), "o"))
        self.assertEqual(code, 2)
        with self.assertRaises(ValueError) as ctx:
            indoormap.load_cloud(path)
        self.assertIn(path, str(ctx.exception))
        self.assertEqual(problem(str(ctx.exception)), problem(err.strip()))

    def test_bad_arrays(self):
        for array, expected in [
            (np.zeros((10, 2), np.float32), "expected an (N, 3) array"),
            (np.zeros((4, 3, 1)), "expected an (N, 3) array"),
            (np.full((5, 3), np.nan), "no finite point"),
            (np.array([["a", "b", "c"]]), "expected an (N, 3) array"),
        ]:
            with self.assertRaises(ValueError) as ctx:
                indoormap.run_pipeline(array)
            self.assertIn("<numpy array>", str(ctx.exception))
            self.assertIn(expected, str(ctx.exception))


if __name__ == "__main__":
    unittest.main()
