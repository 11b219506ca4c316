#!/usr/bin/env python3
"""Writes docs/evaluation.md from its template and the outputs of scripts/eval_report.sh.

Usage: eval_report.py OUT TEMPLATE COMMIT OFFSETS > docs/evaluation.md
OUT holds what eval_report.sh ran: objects_*.txt, sparse_*.txt, positions.txt, jacobs.txt and
floors_<offset>/ (scripts/floor_eval.sh's directories, whose eval.json files are read here).
Every figure written comes from those files; each target is checked here, never typed in.
"""
import datetime
import json
import os
import platform
import re
import sys

out, template, commit, offsets = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4].split()
MODES = ["tdtk", "merged", "mobile-traj", "mobile"]
MODE_NAMES = {"tdtk": "3DTK scans (a pose each)", "merged": "merged cloud, --scanner per position",
              "mobile-traj": "mobile, --trajectory", "mobile": "mobile, no positions"}


def read(name):
    path = os.path.join(out, name)
    if not os.path.exists(path):
        sys.exit("eval_report: %s is missing" % path)
    return open(path).read()


def met(ok):
    return "met" if ok else "**not met**"


def table(head, rows):
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


# Objects: the totals line of scripts/objects_eval.sh.
OBJ = re.compile(r"seeds (\d+-\d+): truth (\d+) result (\d+) matched (\d+) recall ([\d.]+) "
                 r"precision ([\d.]+) median \|dz\| ([\d.]+) m, objects below min area (\d+)")


def objects(name):
    m = [OBJ.search(l) for l in read(name).splitlines()]
    m = [x for x in m if x]
    if not m:
        sys.exit("eval_report: no totals in " + name)
    s, t, r, mt, rec, pre, dz, small = m[-1].groups()
    return dict(seeds=s, truth=int(t), written=int(r), matched=int(mt), recall=float(rec),
                precision=float(pre), dz=float(dz), small=int(small))


def sparse(name):
    """The totals table of scripts/sparse_eval.sh: one dict per case."""
    rows = [l.split() for l in read(name).splitlines() if l.strip() and not l.startswith(" ")]
    head = next((r for r in rows if r and r[0] == "case"), None)
    if head is None:
        sys.exit("eval_report: no table in " + name)
    return {r[0]: dict(zip(head, r)) for r in rows[rows.index(head) + 1:] if len(r) == len(head)}


def border(row):
    a, b = row["border"].split("/")
    return int(a), int(b)


def storeys(eval_json):
    e = json.load(open(eval_json))
    if e.get("storeys"):
        return [(s["k"], s) for s in e["storeys"]]
    return [(0, e)]


def g(d, *keys):
    for k in keys:
        if not isinstance(d, dict) or d.get(k) is None:
            return None
        d = d[k]
    return d


def buildings(offset):
    """Per storey of every building and mode of floor_eval.sh (SEED_OFFSET offset)."""
    base = os.path.join(out, "floors_" + offset)
    rows = []
    for rooms in (4, 8, 12):
        for n in (1, 2):
            seed = 100 + int(offset) + rooms * 10 + n
            for mode in MODES:
                path = os.path.join(base, "r%d_s%d" % (rooms, n), mode, "eval", "eval.json")
                if not os.path.exists(path):
                    rows.append(dict(case="r%d_s%d" % (rooms, n), seed=seed, mode=mode, k="-",
                                     failed=True))
                    continue
                for k, s in storeys(path):
                    fl, r, o = s.get("floor", {}), s.get("rooms", {}), s.get("objects", {})
                    rows.append(dict(
                        case="r%d_s%d" % (rooms, n), seed=seed, mode=mode, k=k, failed=False,
                        doors=g(fl, "doors", "doors") or 0, open=g(fl, "doors", "open") or 0,
                        comps=g(fl, "reachability", "components"),
                        seen=g(fl, "map", "seen_free_iou", "iou") or 0.0,
                        all=g(fl, "map", "free_iou_all", "iou") or 0.0,
                        floor_err=s.get("floor_error_m"),
                        furn=g(fl, "map", "furniture_free", "share") or 0.0,
                        truth_rooms=r.get("truth_rooms", 0), found=r.get("found", 0),
                        within=r.get("within_tolerance", 0), truth_doors=r.get("truth_doors", 0),
                        doors_found=r.get("doors_found", 0),
                        obj_truth=o.get("truth_count", 0), obj_matched=o.get("matched", 0),
                        obj_written=o.get("result_count", 0),
                        obj_matched_all=o.get("matched_all", 0),
                        outside=r.get("objects_outside_rooms", 0)))
    return rows


def pooled(rows):
    ok = [r for r in rows if not r["failed"]]
    s = lambda k: sum(r[k] for r in ok)
    return dict(
        runs=len(rows), failed=len(rows) - len(ok), open=s("open"), doors=s("doors"),
        min_open=min((r["open"] / r["doors"] for r in ok if r["doors"]), default=0.0),
        comps_bad=sum(1 for r in ok if r["comps"] != 1),
        min_seen=min((r["seen"] for r in ok), default=0.0), storeys=len(ok),
        seen_below=sum(1 for r in ok if r["seen"] < 0.9), truth_rooms=s("truth_rooms"),
        found=s("found"), within=s("within"), truth_doors=s("truth_doors"),
        doors_found=s("doors_found"), obj_truth=s("obj_truth"), obj_matched=s("obj_matched"),
        obj_written=s("obj_written"), obj_matched_all=s("obj_matched_all"), outside=s("outside"))


def ratio(a, b):
    return a / b if b else 0.0


def f3(v):
    return "-" if v is None else "%.3f" % v


def objects_section(tune, held):
    rows = [["%s (%s)" % (o["seeds"], role), o["truth"], o["written"], o["matched"],
             "%.3f" % o["recall"], "%.3f" % o["precision"], "%.3f" % o["dz"], o["small"]]
            for o, role in ((tune, "tuning"), (held, "held out"))]
    return table(["seeds", "truth items >= 0.1 m2", "written", "matched", "recall",
                  "precision (everything written)", "median abs. z_max error (m)",
                  "objects below min_area_m2"], rows)


SPARSE_HEAD = ["case", "seeds", "runs without a map", "object recall", "object precision",
               "median dz (m)", "rooms within 0.15 m, 3 %", "map.pgm seen IoU", "map.pgm IoU, all",
               "layout seen IoU", "layout IoU, all", "far free, map (m2 / share)",
               "far free, layout"]
SPARSE_KEYS = ["case", "seeds", "fail", "recall", "precis", "dz_med", "border", "map_seen",
               "map_all", "lay_seen", "lay_all", "map_far", "lay_far"]


def single_section(tune, held):
    rows = [["default step (0.25 deg), seeds 1-20 (tuning)"] + [tune["default"][k]
                                                                for k in SPARSE_KEYS[1:]]]
    names = {"default": "default step (0.25 deg)", "1": "1 deg", "2": "2 deg",
             "16beam": "16-beam lidar"}
    for c in ("default", "1", "2", "16beam"):
        if c in held:
            rows.append(["%s, seeds 21-40 (held out)" % names[c]] +
                        [held[c][k] for k in SPARSE_KEYS[1:]])
    return table(SPARSE_HEAD, rows)


POS = re.compile(r"spots (\d+)-(\d+): areas ([\d.]+) / ([\d.]+) m2 \(([\d.]+) %\), "
                 r"Hausdorff ([\d.]+) m")


def positions():
    text = read("positions.txt")
    pairs = [m.groups() for m in map(POS.search, text.splitlines()) if m]
    if len(pairs) != 10:
        sys.exit("eval_report: positions.txt has %d pairs, not 10" % len(pairs))
    within = sum(1 for p in pairs if float(p[4]) <= 5.0 and float(p[5]) <= 0.2)
    rows = [["%s-%s" % p[:2], "%s / %s" % p[2:4], p[4], p[5]] for p in pairs]
    return within, table(["spots", "areas (m2)", "area difference (%)", "Hausdorff (m)"], rows)


def jacobs():
    text = read("jacobs.txt")
    if "data absent" in text:
        return None, "Not run: the shared data was absent (`%s`)." % text.strip()
    full = re.search(r"rooms.geojson (\d+) rooms \(largest ([\d.]+) m2.*\), (\d+) doors", text)
    room = re.search(r"room.geojson ([\d.]+) m2", text)
    objs = re.search(r"objects: (\d+) written \((\d+) lamps\), smallest ([\d.]+) m2, "
                     r"min_area_m2 ([\d.]+), below it (\d+), left over (\d+) cells", text)
    parts = re.findall(r"part (\S+): levelled (\d) tilt ([\d.]+) deg, off the full scan's up "
                       r"([\d.]+) deg, horizon (\S+) %, warned (\d)", text)
    if not (full and room and objs and len(parts) == 12):
        sys.exit("eval_report: jacobs.txt is incomplete")
    lines = [l for l in text.splitlines() if l.startswith("jacobs full") or
             l.startswith("jacobs objects")]
    rows = [[p[0], "yes" if p[1] == "1" else "no (left as it is)", p[2], p[3], p[4],
             "yes" if p[5] == "1" else "no"] for p in parts]
    body = "\n".join("- " + l.replace("jacobs ", "", 1) for l in lines) + "\n\n" + table(
        ["scans", "levelled", "tilt (deg)", "up direction off the full scan's (deg)",
         "horizon seen (%)", "warned"], rows)
    facts = dict(area=float(full.group(2)), doors=int(full.group(3)), room_area=float(room.group(1)),
                 below=int(objs.group(5)),
                 parts_ok=all(p[5] == "1" and (p[1] == "0" or float(p[3]) <= 0.3) for p in parts))
    return facts, body


def buildings_section(offset, rows):
    pooled_rows = []
    for mode in MODES:
        p = pooled([r for r in rows if r["mode"] == mode])
        pooled_rows.append([
            MODE_NAMES[mode], "%d of %d" % (p["storeys"], p["runs"] + 0),
            "%d of %d (lowest storey %.2f)" % (p["open"], p["doors"], p["min_open"]),
            "%d" % p["comps_bad"], "%.3f" % p["min_seen"],
            "%d of %d (%.0f %%)" % (p["within"], p["truth_rooms"], 100 * ratio(p["within"],
                                                                             p["truth_rooms"])),
            "%d of %d" % (p["found"], p["truth_rooms"]),
            "%d of %d" % (p["doors_found"], p["truth_doors"]),
            "%.3f / %.3f (%d)" % (ratio(p["obj_matched"], p["obj_truth"]),
                                  ratio(p["obj_matched_all"], p["obj_written"]), p["obj_written"]),
            p["outside"]])
    head = ["mode", "storeys mapped", "doors open", "storeys with unreachable scanners",
            "lowest seen-free IoU", "rooms within 0.15 m, 3 %", "rooms found", "doors found",
            "objects recall / precision (written)", "objects in no room"]
    detail = []
    for r in rows:
        if r["failed"]:
            detail.append([r["case"], r["seed"], r["mode"], "pcd-to-map failed"] + [""] * 9)
            continue
        detail.append([r["case"], r["seed"], r["mode"], r["k"], "%d / %d" % (r["open"], r["doors"]),
                       r["comps"], f3(r["seen"]), f3(r["all"]), f3(r["floor_err"]), f3(r["furn"]),
                       "%d / %d found, %d within" % (r["found"], r["truth_rooms"], r["within"]),
                       "%d / %d" % (r["doors_found"], r["truth_doors"]),
                       "%d of %d / %d of %d" % (r["obj_matched"], r["obj_truth"],
                                                r["obj_matched_all"], r["obj_written"])])
    dhead = ["building", "seed", "mode", "storey", "doors open", "scanner components",
             "seen-free IoU", "free IoU, all", "floor error (m)", "furniture called free",
             "rooms", "doors found", "objects matched: recall / precision"]
    return (table(head, pooled_rows) + "\n\n<details><summary>Per storey</summary>\n\n" +
            table(dhead, detail) + "\n\n</details>")


def targets(held_obj, single, pos_within, jac, floors):
    rows = []
    add = lambda issue, item, value, ok: rows.append([issue, item, value, met(ok)])
    d = single["default"]
    add(17, "seeds 21-40, default step: object recall >= 0.9", "%.3f" % held_obj["recall"],
        held_obj["recall"] >= 0.9)
    add(17, "... object precision (everything written) >= 0.9", "%.3f" % held_obj["precision"],
        held_obj["precision"] >= 0.9)
    add(17, "... median height error <= 0.05 m", "%.3f m" % held_obj["dz"], held_obj["dz"] <= 0.05)
    add(17, "... no object below min_area_m2", held_obj["small"], held_obj["small"] == 0)
    add(17, "... room polygon within 0.15 m and 3 % on >= 18 of 20", d["border"],
        border(d)[0] >= 18)
    add(17, "... free-space IoU over the seen cells >= 0.9 (map.pgm, mean)", d["map_seen"],
        float(d["map_seen"]) >= 0.9)
    one = single.get("1")
    if one:
        add(17, "seeds 21-40, 1 degree: object recall >= 0.8", one["recall"],
            float(one["recall"]) >= 0.8)
        add(17, "... object precision >= 0.8", one["precis"], float(one["precis"]) >= 0.8)
        add(17, "... median height error <= 0.05 m", one["dz_med"] + " m",
            float(one["dz_med"]) <= 0.05)
        add(17, "... room polygons within on >= 16 of 20", one["border"], border(one)[0] >= 16)
        add(17, "... free-space IoU over the seen cells >= 0.8", one["map_seen"],
            float(one["map_seen"]) >= 0.8)
    add(17, "the same room from two positions: 10 of 10 pairs within 5 % and 0.2 m",
        "%d of 10" % pos_within, pos_within == 10)
    if jac:
        add(17, "Jacobs: no object below min_area_m2", jac["below"], jac["below"] == 0)
        add(17, "Jacobs: room polygon 28-40 m2 (room.geojson)", "%.1f m2" % jac["room_area"],
            28 <= jac["room_area"] <= 40)
        add(16, "Jacobs: one room of 28-40 m2 with its door (rooms.geojson)",
            "%.1f m2, %d door" % (jac["area"], jac["doors"]),
            28 <= jac["area"] <= 40 and jac["doors"] >= 1)
        add(17, "Jacobs sectors (9 single, 3 of three): warned, and levelled within 0.3 deg or "
            "not at all", "see below", jac["parts_ok"])
    for offset, rows_b in floors:
        name = "tuning seeds" if offset == "0" else "held-out seeds (SEED_OFFSET=%s)" % offset
        for mode in MODES:
            p = pooled([r for r in rows_b if r["mode"] == mode])
            tag = "%s, %s" % (name, MODE_NAMES[mode])
            ok15 = (p["failed"] == 0 and p["min_open"] >= 0.95 and p["comps_bad"] == 0 and
                    p["min_seen"] >= 0.9)
            add(15, tag + ": every storey >= 95 % doors open, every scanner reachable, "
                "seen-free IoU >= 0.9", "lowest %.2f doors, %d unreachable, lowest IoU %.3f" % (
                    p["min_open"], p["comps_bad"], p["min_seen"]), ok15)
            w = ratio(p["within"], p["truth_rooms"])
            rec = ratio(p["obj_matched"], p["obj_truth"])
            pre = ratio(p["obj_matched_all"], p["obj_written"])
            add(16, tag + ": every room found, >= 90 % within 0.15 m and 3 %, >= 95 % doors found",
                "%d of %d found, %.0f %% within, %.0f %% doors" % (
                    p["found"], p["truth_rooms"], 100 * w,
                    100 * ratio(p["doors_found"], p["truth_doors"])),
                p["found"] == p["truth_rooms"] and w >= 0.9 and
                ratio(p["doors_found"], p["truth_doors"]) >= 0.95)
            add(16, tag + ": objects recall and precision >= 0.9, none in a wall",
                "%.3f / %.3f, %d in no room" % (rec, pre, p["outside"]),
                rec >= 0.9 and pre >= 0.9 and p["outside"] == 0)
    return table(["issue", "acceptance item", "measured", "status"], rows)


def main():
    tune_obj, held_obj = objects("objects_1_20.txt"), objects("objects_21_40.txt")
    tune_single, held_single = sparse("sparse_1_20.txt"), sparse("sparse_21_40.txt")
    pos_within, pos_table = positions()
    jac, jac_body = jacobs()
    floors = [(o, buildings(o)) for o in offsets]
    sections = {
        "GENERATED": "Generated by `scripts/eval_report.sh` on %s, commit %s, on %s (%d cores), "
                     "from `docs/evaluation.md.in`: do not edit this page, edit the template or "
                     "the scripts and run it again." % (
                         datetime.date.today().isoformat(), commit,
                         platform.node() or "an unnamed machine", os.cpu_count() or 0),
        "TARGETS": targets(held_obj, held_single, pos_within, jac, floors),
        "OBJECTS": objects_section(tune_obj, held_obj),
        "SINGLE": single_section(tune_single, held_single),
        "POSITIONS": "**%d of 10** pairs within 5 %% area and 0.2 m.\n\n%s" % (pos_within,
                                                                            pos_table),
        "JACOBS": jac_body,
        "BUILDINGS": "\n\n".join(
            "#### %s\n\n%s" % ("Tuning seeds (141 ... 222)" if o == "0" else
                               "Held-out seeds (SEED_OFFSET=%s: %d ... %d)" % (
                                   o, 141 + int(o), 222 + int(o)), buildings_section(o, rows))
            for o, rows in floors),
    }
    text = open(template).read()
    for key, value in sections.items():
        marker = "@@%s@@" % key
        if marker not in text:
            sys.exit("eval_report: the template has no " + marker)
        text = text.replace(marker, value)
    left = re.findall(r"@@[A-Z_]+@@", text)
    if left:
        sys.exit("eval_report: no figures for " + ", ".join(left))
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
