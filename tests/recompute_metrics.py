#!/usr/bin/env python3
"""Recompute ballbench's metrics from a trajectory CSV, independently of the C++ code, and compare
them with the JSON results. Standard library only (tomllib reads the scene file).

usage: recompute_metrics.py SCENE.toml TRAJECTORY.csv RESULTS.json

It rebuilds the scene's radii, masses and moments of inertia (k m r^2, `inertia`) (explicit [[ball]] only, or a results file whose scene
has random or lattice balls: then radii and masses are taken from each [random] or [lattice]
group), follows the
glossary's definitions (reports/REPORT.md) and exits 1 naming every metric that disagrees.
"""
import csv
import json
import math
import sys
import tomllib
from collections import defaultdict


def scene_balls(scene):
    radii, masses = [], []
    for b in scene.get("ball", []):
        radii.append(b["radius"])
        masses.append(b.get("mass", 1.0))
    for key in ("random", "lattice"):
        groups = scene.get(key)
        for group in ([groups] if isinstance(groups, dict) else groups or []):
            radii += [group["radius"]] * group["count"]
            masses += [group.get("mass", 1.0)] * group["count"]
    return radii, masses


def recompute(scene, samples, times, radii, masses, tol, stuck, roll_tol, spins):
    """samples: per sample, per ball (x, y, vx, vy, w); spins: whether the trajectory has w."""
    g = scene.get("gravity", [0.0, 0.0])
    box = scene.get("container")
    is_box = box is not None and box.get("kind", "box") == "box"
    n = len(radii)
    k_inertia = 0.4 if scene.get("inertia", "disk") == "sphere" else 0.5
    moments = [k_inertia * m * r * r for m, r in zip(masses, radii)]
    # Angular momentum is taken about the box's centre, or the initial centre of mass.
    if is_box:
        cx, cy = 0.5 * (box["min"][0] + box["max"][0]), 0.5 * (box["min"][1] + box["max"][1])
    else:
        total = sum(masses)
        cx = sum(m * b[0] for m, b in zip(masses, samples[0])) / total
        cy = sum(m * b[1] for m, b in zip(masses, samples[0])) / total
    # Potential reference: the lowest point of the box along g (or the lowest initial ball).
    if is_box:
        (x0, y0), (x1, y1) = box["min"], box["max"]
        ref = min(-(g[0] * x + g[1] * y) for x in (x0, x1) for y in (y0, y1))
    else:
        ref = min(-(g[0] * x + g[1] * y) for x, y, _, _, _ in samples[0])

    def advance(run, leaving):
        # A run of deep overlap: counted once, when longer than `stuck` samples and not moving out;
        # negative once counted.
        if run < 0:
            return run - 1, 0
        run += 1
        if run > stuck and not leaving:
            return -run, 1
        return run, 0

    def energy(s):
        return sum(m * (0.5 * (vx * vx + vy * vy) + (-(g[0] * x + g[1] * y) - ref)) + 0.5 * i * w * w
                   for m, i, (x, y, vx, vy, w) in zip(masses, moments, s))

    def angular(s):
        return sum(m * ((x - cx) * vy - (y - cy) * vx) + i * w for m, i, (x, y, vx, vy, w) in zip(masses, moments, s))

    def slip(s):
        """The largest |v . t - w r| of a ball within r (1 + tol) of a wall, or None if none is."""
        worst = None
        for r, (x, y, vx, vy, w) in zip(radii, s):
            for gap, vt in ((x - box["min"][0], vy), (box["max"][0] - x, -vy), (y - box["min"][1], -vx),
                            (box["max"][1] - y, vx)):
                if gap <= r * (1 + tol):
                    worst = max(worst or 0.0, abs(vt - w * r))
        return worst

    def momentum(s):
        return (sum(m * b[2] for m, b in zip(masses, s)), sum(m * b[3] for m, b in zip(masses, s)))

    def beyond(x, y):
        return is_box and (x < box["min"][0] or x > box["max"][0] or y < box["min"][1] or y > box["max"][1])

    e0, p0, l0 = energy(samples[0]), momentum(samples[0]), angular(samples[0])
    out = {"energy_initial": e0, "energy_final": energy(samples[-1]), "momentum_drift": 0.0, "energy_abs_drift": 0.0,
           "angular_initial": l0, "angular_final": angular(samples[-1]), "angular_drift": 0.0,
           "tunnelling_wall": 0, "tunnelling_pair": 0, "sticking_wall": 0, "sticking_pair": 0}
    if spins and is_box:  # the time from which no ball on a wall slips: the start of the last run of rolling samples
        touched, rolling_since = False, None
        for t, s in zip(times, samples):
            worst = slip(s)
            touched = touched or worst is not None
            if (worst or 0.0) > roll_tol:
                rolling_since = None
            elif rolling_since is None:
                rolling_since = t
        out["slip_final_max"] = slip(samples[-1]) or 0.0
        out["time_to_roll"] = rolling_since if touched else None
    pen_max, pen_sum, pen_count = 0.0, 0.0, 0
    pair_run, wall_run = defaultdict(int), [0] * n
    prev = None
    for k, s in enumerate(samples):
        h = times[k] - times[k - 1] if k else 0.0
        out["energy_abs_drift"] = max(out["energy_abs_drift"], abs(energy(s) - e0))
        p = momentum(s)
        out["momentum_drift"] = max(out["momentum_drift"], math.hypot(p[0] - p0[0], p[1] - p0[1]))
        out["angular_drift"] = max(out["angular_drift"], abs(angular(s) - l0))
        if prev is not None:
            out["tunnelling_wall"] += sum(1 for a, b in zip(prev, s) if not beyond(a[0], a[1]) and beyond(b[0], b[1]))
        new_run = defaultdict(int)
        for i in range(n):
            for j in range(i + 1, n):
                rs = radii[i] + radii[j]
                dx, dy = s[i][0] - s[j][0], s[i][1] - s[j][1]
                d = math.hypot(dx, dy)
                if d < rs:
                    depth = rs - d
                    rel = depth / min(radii[i], radii[j])
                    pen_max, pen_sum, pen_count = max(pen_max, rel), pen_sum + rel, pen_count + 1
                    if depth > tol * rs:
                        leaving = dx * (s[i][2] - s[j][2]) + dy * (s[i][3] - s[j][3]) > 0
                        new_run[(i, j)], counted = advance(pair_run[(i, j)], leaving)
                        out["sticking_pair"] += counted
                if prev is not None:
                    ax, ay = prev[i][0] - prev[j][0], prev[i][1] - prev[j][1]
                    if math.hypot(ax, ay) >= rs and d >= rs:
                        wx, wy = dx - ax, dy - ay
                        ww = wx * wx + wy * wy
                        t = min(1.0, max(0.0, -(ax * wx + ay * wy) / ww)) if ww > 0 else 0.0
                        # The chord may stray (|dv_i| + |dv_j|) h / 4 from paths bent by collisions.
                        dvi = math.hypot(s[i][2] - prev[i][2], s[i][3] - prev[i][3])
                        dvj = math.hypot(s[j][2] - prev[j][2], s[j][3] - prev[j][3])
                        bend = 0.25 * h * (dvi + dvj)
                        if math.hypot(ax + t * wx, ay + t * wy) < (1 - tol) * rs - bend:
                            out["tunnelling_pair"] += 1
        pair_run = new_run
        if is_box:
            for i, (x, y, _, _, _) in enumerate(s):
                vx, vy = s[i][2], s[i][3]
                # The nearest wall (the first of equal gaps) and the speed along its inward normal.
                gap, inward = min([(x - box["min"][0], vx), (box["max"][0] - x, -vx), (y - box["min"][1], vy),
                                   (box["max"][1] - y, -vy)], key=lambda g: g[0])
                depth = radii[i] - gap
                if depth > 0:
                    pen_max, pen_sum, pen_count = max(pen_max, depth / radii[i]), pen_sum + depth / radii[i], pen_count + 1
                if depth > tol * radii[i]:
                    wall_run[i], counted = advance(wall_run[i], inward > 0)
                    out["sticking_wall"] += counted
                else:
                    wall_run[i] = 0
        prev = s
    out["penetration_max"] = pen_max
    out["penetration_mean"] = pen_sum / pen_count if pen_count else 0.0
    return out


def main():
    scene_path, csv_path, json_path = sys.argv[1:4]
    with open(scene_path, "rb") as f:
        scene = tomllib.load(f)
    results = json.load(open(json_path))
    radii, masses = scene_balls(scene)
    runs = defaultdict(lambda: defaultdict(list))
    run_times = defaultdict(dict)
    with open(csv_path) as f:
        reader = csv.DictReader(f)
        spins = "w" in reader.fieldnames  # a scene that rotates: angular velocities follow
        for row in reader:
            label = row["engine"] if row["profile"] == "default" else f'{row["engine"]}/{row["profile"]}'
            w = float(row["w"]) if spins else 0.0
            runs[label][int(row["step"])].append((float(row["x"]), float(row["y"]), float(row["vx"]), float(row["vy"]), w))
            run_times[label][int(row["step"])] = float(row["t"])
    bad = []
    for r in results:
        label = r["engine"] if r["profile"] == "default" else f'{r["engine"]}/{r["profile"]}'
        if r["status"] == "unsupported":  # never ran (say, a Node engine without Node): no trajectory
            print(f"{label}: unsupported, nothing to check ({r['error']})")
            continue
        steps = runs[label]
        samples = [steps[k] for k in sorted(steps)]
        if len(samples) != r["steps_done"] + 1 or any(len(s) != len(radii) for s in samples):
            bad.append(f"{label}: trajectory has {len(samples)} samples, JSON says {r['steps_done']} steps")
            continue
        cfg = r["metrics_config"]
        times = [run_times[label][k] for k in sorted(steps)]
        got = recompute(scene, samples, times, radii, masses, cfg["contact_tolerance"], cfg["stuck_samples"],
                        cfg["roll_tolerance"], spins)
        want = {"energy_initial": r["energy"]["initial"], "energy_final": r["energy"]["final"],
                "energy_abs_drift": r["energy"]["max_abs_drift"], "momentum_drift": r["momentum"]["max_abs_drift"],
                "angular_initial": r["angular_momentum"]["initial"], "angular_final": r["angular_momentum"]["final"],
                "angular_drift": r["angular_momentum"]["max_abs_drift"],
                "tunnelling_wall": r["tunnelling"]["wall"], "tunnelling_pair": r["tunnelling"]["pair"],
                "sticking_wall": r["sticking"]["wall"], "sticking_pair": r["sticking"]["pair"],
                "penetration_max": r["penetration"]["max"], "penetration_mean": r["penetration"]["mean"]}
        if "slip_final_max" in got:
            if r["slip"] is None:
                bad.append(f"{label}: the scene rotates and has walls, but the JSON has no slip")
            else:
                want["slip_final_max"] = r["slip"]["final_max"]
                if (got["time_to_roll"] is None) != (r["slip"]["time_to_roll"] is None):
                    bad.append(f"{label}: time_to_roll recomputed {got['time_to_roll']!r}, JSON {r['slip']['time_to_roll']!r}")
                elif got["time_to_roll"] is not None:
                    want["time_to_roll"] = r["slip"]["time_to_roll"]
        for k, w in want.items():
            # Sums of the same doubles in another order: agree to round-off (1e-9 relative of the scale).
            if k.startswith("energy"):
                scale = max(1.0, abs(got["energy_initial"]))
            elif k.startswith("angular"):
                scale = max(1.0, abs(got["angular_initial"]), abs(got["angular_final"]))
            else:
                scale = max(1.0, abs(w))
            ok = got[k] == w if isinstance(w, int) else abs(got[k] - w) <= 1e-9 * scale
            if not ok:
                bad.append(f"{label}: {k} recomputed {got[k]!r}, JSON {w!r}")
        if r["energy"]["max_rel_drift"] is not None and got["energy_initial"] > 0:
            rel = got["energy_abs_drift"] / got["energy_initial"]
            if abs(rel - r["energy"]["max_rel_drift"]) > 1e-9 * max(1.0, rel):
                bad.append(f"{label}: max_rel_drift recomputed {rel!r}, JSON {r['energy']['max_rel_drift']!r}")
        print(f"{label}: {len(samples)} samples checked")
    for b in bad:
        print("MISMATCH", b)
    print(f"{len(results) - len({b.split(':')[0] for b in bad})} passed, {len({b.split(':')[0] for b in bad})} failed")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
