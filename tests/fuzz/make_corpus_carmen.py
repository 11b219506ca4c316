#!/usr/bin/env python3
"""Writes the seed corpus of the carmen fuzz target (tests/fuzz/corpus/carmen/): small hand-made
CARMEN logs, plain and gzip, valid and broken. Rerun after editing."""
import gzip
import os

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "carmen")
os.makedirs(D, exist_ok=True)


def put(name, data):
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(D, name), "wb") as f:
        f.write(data)


def flaser(n, r=1.5, pose="1 2 0.5"):
    return "FLASER %d %s %s %s 12.5 host 12.6\n" % (n, " ".join([str(r)] * n), pose, pose)


head = ("# message formats defined: PARAM SYNC ODOM FLASER\n"
        "PARAM robot_frontlaser_offset 0.1 1.0 host 1.0\n"
        "PARAM robot_front_laser_max 50 1.0 host 1.0\n")
valid = head + "ODOM 0 0 0 0 0 0 1.0 host 1.0\n" + flaser(4) + "NEFF 10\n" + flaser(5, 81.9)
put("valid.log", valid)
put("valid_crlf.log", valid.replace("\n", "\r\r\n"))
put("valid.log.gz", gzip.compress(valid.encode(), mtime=0))
put("truncated.gz", gzip.compress(valid.encode(), mtime=0)[:-20])
put("truncated_line.log", head + flaser(4)[:-15])
put("wrong_count.log", flaser(4).replace("FLASER 4", "FLASER 6"))
put("not_number.log", flaser(3).replace("1.5", "x.5", 1))
put("nan.log", flaser(3).replace("1.5", "nan", 1))
put("huge_count.log", "FLASER 999999999 1 2 3\n")
put("param_bad.log", "PARAM robot_frontlaser_offset abc 1 host 1\n" + flaser(2))
put("no_newline.log", flaser(2).rstrip("\n"))
put("empty.log", "")
