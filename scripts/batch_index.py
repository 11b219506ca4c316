#!/usr/bin/env python3
"""The index of a batch run (docs/batch.md): OUTROOT/index.csv and OUTROOT/index.json.

Usage: batch_index.py OUTROOT

Reads OUTROOT/status/*.tsv (one per input, written by `scripts/batch.sh --run-one`: K, input
line, output directory name, exit code, seconds, log) and, for the inputs that succeeded, the main
figures of their summary.json (the first mapped storey's when the cloud has several). An input of
OUTROOT/inputs.txt (`batch.sh --prepare`) without a status line, whose run was killed before it
ended (a Slurm time or memory limit, a lost node, parallel stopped), gets a row with status
"not run". Writes both files atomically (temporary name, then rename). Exit code: 0 when every
input succeeded, 1 when one failed or did not run, 2 when there is no status at all.
"""
import csv
import io
import json
import os
import sys

COLUMNS = ["k", "input", "outdir", "status", "exit_code", "seconds", "error", "points_kept",
           "grid_cells", "floor_z_m", "room_height_m", "storeys", "objects", "rooms",
           "room_closed", "room_area_m2", "warnings", "log"]


def figures(outdir):
    """Main figures of outdir/summary.json (or of its first mapped storey's)."""
    path = os.path.join(outdir, "summary.json")
    with open(path, encoding="utf-8") as f:
        s = json.load(f)
    storeys = s.get("storeys", [])
    if "points" not in s:  # several storeys: OUTROOT/storey_<k>/summary.json
        mapped = [st for st in storeys if st.get("mapped")]
        with open(os.path.join(outdir, mapped[0]["dir"], "summary.json"), encoding="utf-8") as f:
            s = json.load(f)
    border = s.get("border") or {}
    return {
        "points_kept": s["points"]["kept"],
        "grid_cells": "x".join(str(v) for v in s["grid"]["size_cells"][:2]),
        "floor_z_m": round(s["floor_z_m"], 3),
        "room_height_m": round(s["room_height_m"], 3),
        "storeys": max(1, len(storeys)),
        "objects": (s.get("objects") or {}).get("count"),
        "rooms": (s.get("rooms") or {}).get("count"),
        "room_closed": border.get("closed"),
        "room_area_m2": round(border["area_m2"], 2) if border.get("closed") else None,
        "warnings": len(s.get("warnings", [])),
    }


def last_line(path):
    """The last line of a log that says something."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            # CLI11's usage errors end with a pointer to --help: the line before it says what.
            lines = [l.strip() for l in f
                     if l.strip() and l.strip() != "Run with --help for more information."]
        return lines[-1] if lines else ""
    except OSError:
        return ""


def row_of(outroot, fields):
    k, line, name, code, secs, log = fields
    row = {c: None for c in COLUMNS}
    row.update(k=int(k), input=line, outdir=name, exit_code=int(code), seconds=float(secs), log=log)
    row["status"] = "ok" if row["exit_code"] == 0 else "failed"
    if row["exit_code"] == 0:
        try:
            row.update(figures(os.path.join(outroot, name)))
        except (OSError, ValueError, KeyError, IndexError, TypeError) as e:
            row["status"], row["error"] = "failed", f"summary.json unreadable: {e}"
    else:
        row["error"] = last_line(os.path.join(outroot, log))
    return row


def missing_rows(outroot, done):
    """Rows for the inputs of OUTROOT/inputs.txt whose run left no status line."""
    try:
        with open(os.path.join(outroot, "inputs.txt"), encoding="utf-8") as f:
            lines = [l.rstrip("\n") for l in f]
    except OSError:
        return []  # an OUTROOT of an older batch.sh: only the status lines are known
    rows = []
    for k, line in enumerate(lines, start=1):
        if k not in done:
            row = {c: None for c in COLUMNS}
            row.update(k=k, input=line, status="not run",
                       error="no status line: the run of this input did not finish")
            rows.append(row)
    return rows


def csv_cell(value):
    """None as an empty cell, booleans as JSON spells them."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    return value


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8", newline="") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    outroot = sys.argv[1]
    status = os.path.join(outroot, "status")
    names = sorted(n for n in os.listdir(status) if n.endswith(".tsv")) if os.path.isdir(status) else []
    rows = []
    for n in names:
        with open(os.path.join(status, n), encoding="utf-8") as f:
            fields = f.read().rstrip("\n").split("\t")
        rows.append(row_of(outroot, fields))
    rows += missing_rows(outroot, {r["k"] for r in rows})
    if not rows:
        print(f"batch_index.py: no status in {status} and no {outroot}/inputs.txt: nothing ran",
              file=sys.stderr)
        return 2
    rows.sort(key=lambda r: r["k"])
    failed = [r for r in rows if r["status"] == "failed"]
    not_run = [r for r in rows if r["status"] == "not run"]
    ok = len(rows) - len(failed) - len(not_run)
    write_atomic(os.path.join(outroot, "index.json"), json.dumps(
        {"inputs": len(rows), "ok": ok, "failed": len(failed), "not_run": len(not_run),
         "rows": rows}, indent=2) + "\n")
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({c: csv_cell(r[c]) for c in COLUMNS})
    write_atomic(os.path.join(outroot, "index.csv"), buf.getvalue())
    print(f"batch: {len(rows)} inputs, {ok} done, {len(failed)} failed, {len(not_run)} not run; "
          f"index: {os.path.join(outroot, 'index.csv')}, index.json", file=sys.stderr)
    for r in failed + not_run:
        code = "" if r["exit_code"] is None else f" (exit {r['exit_code']})"
        print(f"batch: {r['status']}: {r['input']}{code}: {r['error']}", file=sys.stderr)
    return 1 if failed or not_run else 0


if __name__ == "__main__":
    sys.exit(main())
