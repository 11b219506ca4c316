"""scripts/eval_report.py, the writer of docs/evaluation.md: it fills the template with the
figures of the evaluation scripts' outputs and checks every target itself (never typed in), and
the committed page is its output (no hand edits). The outputs here are small hand-written
stand-ins with known figures; the real ones come from scripts/eval_report.sh."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

from support import SOURCE_DIR

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "eval_report.py")
TEMPLATE = os.path.join(SOURCE_DIR, "docs", "evaluation.md.in")
MODES = ["tdtk", "merged", "mobile-traj", "mobile"]


def objects_line(first, last, recall, precision):
    return ("seeds %d-%d: truth 20 result 20 matched %d recall %.3f precision %.3f median |dz| "
            "0.020 m, objects below min area 0\n" % (first, last, round(recall * 20), recall,
                                                     precision))


SPARSE_HEAD = ("case    seeds  fail  recall  precis dz_med  border map_seen  map_all lay_seen  "
               "lay_all   map_far   lay_far\n")


def sparse_row(case, recall, border, seen):
    return ("%s 20 0 %.3f 0.900 0.020 %s %.3f 0.600 0.800 0.500 0.04/0.000 0.04/0.000\n" % (
        case, recall, border, seen))


def storey(within, truth_rooms, seen, matched, truth, written, matched_all):
    return {"floor": {"doors": {"doors": 4, "open": 4},
                      "reachability": {"components": 1},
                      "map": {"seen_free_iou": {"iou": seen}, "free_iou_all": {"iou": seen},
                              "furniture_free": {"share": 0.01}}},
            "rooms": {"truth_rooms": truth_rooms, "found": truth_rooms,
                      "within_tolerance": within, "truth_doors": 4, "doors_found": 4,
                      "objects_outside_rooms": 0},
            "objects": {"truth_count": truth, "matched": matched, "result_count": written,
                        "matched_all": matched_all}}


class EvalReport(unittest.TestCase):
    def write_outputs(self, out, held_recall=0.95, seen=0.95):
        files = {
            "objects_1_20.txt": objects_line(1, 20, 0.95, 0.95),
            "objects_21_40.txt": objects_line(21, 40, held_recall, 0.85),
            "sparse_1_20.txt": SPARSE_HEAD + sparse_row("default", 0.95, "20/20", 0.94),
            "sparse_21_40.txt": SPARSE_HEAD + sparse_row("default", held_recall, "17/20", 0.93) +
            sparse_row("1", 0.85, "16/20", 0.92),
            "positions.txt": "".join(
                "[ figures  ] spots %d-%d: areas 50.00 / 50.50 m2 (1.0 %%), Hausdorff 0.050 m\n" %
                (k, k + 1) for k in range(10)),
            "jacobs.txt": (
                "jacobs full: levelled 1 tilt 2.13 deg, room.geojson 36.0 m2 with 1 openings, "
                "rooms.geojson 2 rooms (largest 34.6 m2, others 3.8 m2), 1 doors (0.83 m wide)\n"
                "jacobs objects: 17 written (2 lamps), smallest 0.045 m2, min_area_m2 0.03, "
                "below it 0, left over 1240 cells\n" + "".join(
                    "jacobs part %s: levelled 0 tilt 0.00 deg, off the full scan's up 2.13 deg, "
                    "horizon 14 %%, warned 1\n" % p
                    for p in "0 1 2 3 4 5 6 7 8 0-2 3-5 6-8".split())),
        }
        for name, text in files.items():
            with open(os.path.join(out, name), "w", encoding="utf-8") as f:
                f.write(text)
        for rooms in (4, 8, 12):
            for n in (1, 2):
                for mode in MODES:
                    d = os.path.join(out, "floors_0", "r%d_s%d" % (rooms, n), mode, "eval")
                    os.makedirs(d)
                    # 9 of 10 rooms within, objects 18 of 20 matched, 19 of 20 written right.
                    with open(os.path.join(d, "eval.json"), "w", encoding="utf-8") as f:
                        json.dump(storey(9, 10, seen, 18, 20, 20, 19), f)

    def run_report(self, out):
        return subprocess.run([sys.executable, SCRIPT, out, TEMPLATE, "abc1234", "0"],
                              capture_output=True, text=True, timeout=60, check=False)

    def test_targets_are_checked_from_the_figures(self):
        with tempfile.TemporaryDirectory() as out:
            self.write_outputs(out)
            p = self.run_report(out)
            self.assertEqual(p.returncode, 0, p.stderr)
            page = p.stdout
        self.assertNotIn("@@", page)
        self.assertIn("commit abc1234", page)
        rows = {l.split(" | ")[1]: l for l in page.splitlines() if l.startswith("| 1")}
        self.assertIn("| 0.950 | met |", rows["seeds 21-40, default step: object recall >= 0.9"])
        self.assertIn("| 0.850 | **not met** |",
                      rows["... object precision (everything written) >= 0.9"])
        self.assertIn("| 17/20 | **not met** |",
                      rows["... room polygon within 0.15 m and 3 % on >= 18 of 20"])
        self.assertIn("| 16/20 | met |", rows["... room polygons within on >= 16 of 20"])
        self.assertIn("| 10 of 10 | met |",
                      rows["the same room from two positions: 10 of 10 pairs within 5 % and 0.2 m"])
        within = [l for l in page.splitlines() if "3DTK scans (a pose each): every room found" in l]
        self.assertEqual(len(within), 1)
        self.assertIn("60 of 60 found, 90 % within, 100 % doors | met |", within[0])
        objects = [l for l in page.splitlines() if "3DTK scans (a pose each): objects recall" in l]
        self.assertIn("0.900 / 0.950, 0 in no room | met |", objects[0])

    def test_a_miss_is_reported_as_one(self):
        with tempfile.TemporaryDirectory() as out:
            self.write_outputs(out, held_recall=0.85, seen=0.85)
            p = self.run_report(out)
            self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("| 0.850 | **not met** |", p.stdout)
        nav = [l for l in p.stdout.splitlines() if "every storey >= 95 % doors open" in l]
        self.assertEqual(len(nav), 4)
        self.assertTrue(all("lowest IoU 0.850 | **not met** |" in l for l in nav), nav)

    def test_missing_figures_stop_the_report(self):
        with tempfile.TemporaryDirectory() as out:
            self.write_outputs(out)
            os.remove(os.path.join(out, "positions.txt"))
            p = self.run_report(out)
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("positions.txt", p.stderr)
        self.assertEqual(p.stdout, "")

    def test_the_committed_page_is_the_templates_output(self):
        # Every line of the template without a marker is in docs/evaluation.md, in order: the
        # page is written by the script, not edited by hand.
        with open(TEMPLATE, encoding="utf-8") as f:
            template = [l for l in f.read().splitlines() if "@@" not in l]
        with open(os.path.join(SOURCE_DIR, "docs", "evaluation.md"), encoding="utf-8") as f:
            page = f.read().splitlines()
        at = 0
        for line in template:
            while at < len(page) and page[at] != line:
                at += 1
            self.assertLess(at, len(page), "docs/evaluation.md lacks the template's line: " + line)
            at += 1


if __name__ == "__main__":
    unittest.main()
