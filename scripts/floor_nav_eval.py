#!/usr/bin/env python3
"""Scores pcd-to-map's navigation map (map.pgm / map.yaml) against a scene-sim ground truth:
doors open for a 0.4 m robot, every scanner position reachable from every other, free-space IoU.

Usage: scripts/floor_nav_eval.py SCENE_DIR RESULT_DIR   (prints one JSON line)

The same rules as tests/test_floors_slow.cpp: the configuration space is the free cells whose
centre lies at least 0.2 m (4 cells) from the centre of every cell that is not free (unknown
blocks); a door is open when a configuration-space cell lies within 0.15 m of its centre; the
positions (summary.json scanners_map_m) are reachable when they fall (within 0.5 m) into one
4-connected component. IoU: free cells of map.pgm against the truth's free cells
(ground_truth_layout.pgm), over all cells (the truth also calls unseen space free: see
docs/evaluation.md)."""
import json, re, sys
from collections import deque


def read_pgm(p):
    d = open(p, 'rb').read()
    parts, i = [], 0
    while len(parts) < 4:
        while d[i:i + 1].isspace():
            i += 1
        if d[i:i + 1] == b'#':
            while d[i:i + 1] != b'\n':
                i += 1
            continue
        j = i
        while not d[j:j + 1].isspace():
            j += 1
        parts.append(d[i:j])
        i = j
    i += 1
    w, h = int(parts[1]), int(parts[2])
    return w, h, d[i:i + w * h]


def read_map(pgm, yaml):
    w, h, px = read_pgm(pgm)
    y = open(yaml).read()
    origin = [float(v) for v in re.search(r'origin: \[([^\]]*)\]', y).group(1).split(',')]
    res = float(re.search(r'resolution: ([0-9.eE+-]+)', y).group(1))
    return w, h, px, origin, res  # px row 0 = highest y


def main(scene, result):
    truth = json.load(open(f'{scene}/ground_truth.json'))
    summary = json.load(open(f'{result}/summary.json'))
    w, h, px, o, res = read_map(f'{result}/map.pgm', f'{result}/map.yaml')
    free = bytearray(w * h)  # grid row 0 = lowest y
    for r in range(h):
        row = px[(h - 1 - r) * w:(h - r) * w]
        for c in range(w):
            free[r * w + c] = row[c] == 254
    R = 4
    # distance >= R cells to every non-free cell: erode with the disk of radius < R
    offs = [(dr, dc) for dr in range(-R + 1, R) for dc in range(-R + 1, R) if dr * dr + dc * dc < R * R]
    cs = bytearray(w * h)
    for r in range(R, h - R):
        for c in range(R, w - R):
            i = r * w + c
            if free[i] and all(free[i + dr * w + dc] for dr, dc in offs):
                cs[i] = 1
    lab = [0] * (w * h)
    n = 0
    for i in range(w * h):
        if cs[i] and not lab[i]:
            n += 1
            lab[i] = n
            q = deque([i])
            while q:
                j = q.popleft()
                r, c = divmod(j, w)
                for rr, cc in ((r + 1, c), (r - 1, c), (r, c + 1), (r, c - 1)):
                    k = rr * w + cc
                    if 0 <= rr < h and 0 <= cc < w and cs[k] and not lab[k]:
                        lab[k] = n
                        q.append(k)

    def label_at(x, y, search_m):
        c0, r0 = int((x - o[0]) / res), int((y - o[1]) / res)
        s = int(round(search_m / res))
        for d in range(s + 1):
            for dr in range(-d, d + 1):
                for dc in range(-d, d + 1):
                    r, c = r0 + dr, c0 + dc
                    if 0 <= r < h and 0 <= c < w and lab[r * w + c]:
                        return lab[r * w + c]
        return 0

    doors = [d for room in truth['rooms'] for d in room.get('doors', [])]
    open_ = sum(label_at(d['center'][0], d['center'][1], 0.15) > 0 for d in doors)
    labels = [label_at(p[0], p[1], 0.5) for p in summary['scanners_map_m']]
    reach = bool(labels) and all(l > 0 and l == labels[0] for l in labels)
    tw, th, tpx, to, tres = read_map(f'{scene}/ground_truth_layout.pgm',
                                     f'{scene}/ground_truth_layout.yaml')
    inter = union = 0
    tfree = set()
    for r in range(th):
        row = tpx[(th - 1 - r) * tw:(th - r) * tw]
        for c in range(tw):
            if row[c] == 3 or row[c] == 254:  # class value or ROS grey
                tfree.add((round((to[0] + (c + 0.5) * tres - o[0]) / res - 0.5),
                           round((to[1] + (r + 0.5) * tres - o[1]) / res - 0.5)))
    mfree = {(i % w, i // w) for i in range(w * h) if free[i]}
    inter, union = len(mfree & tfree), len(mfree | tfree)
    print(json.dumps({'doors': len(doors), 'doors_open': open_, 'positions': len(labels),
                      'all_reachable': reach, 'free_iou_all': round(inter / union, 3) if union else None,
                      'free_m2': round(len(mfree) * res * res, 1),
                      'ghosts_applied': summary['ghosts']['applied']}))


if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2])
