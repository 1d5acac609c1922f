#!/usr/bin/env python3
"""A process engine that misbehaves on purpose (tests/test_process_engine.cpp): balls stay put,
and at step 3 it does what argv[1] names. For a scene that rotates its states carry w (each
ball's initial spin) and angle (0), except in mode "no-w", whose states from step 3 on carry no w.
Test-only: never in an engines file."""
import array
import json
import sys
import time

mode = sys.argv[1] if len(sys.argv) > 1 else "none"
out = sys.stdout.buffer


def send(reply, block=b""):
    out.write(json.dumps(reply).encode() + b"\n" + block)
    out.flush()


if mode == "no-hello":
    sys.stderr.write("misbehaving engine: refusing to start\n")
    sys.exit(4)
n, steps, balls, rotation = 0, 0, None, False
for line in sys.stdin.buffer:
    msg = json.loads(line)
    if msg["op"] == "hello":
        if mode == "unavailable":
            send({"ok": False, "kind": "unavailable", "error": "the frobnicator library is not installed"})
            continue
        send({"ok": True, "protocol": 2 if mode == "protocol-2" else 1, "name": "misbehaving", "version": "0",
              "capabilities": {}, "profiles": ["default"], "settings_keys": ["level"]})
    elif msg["op"] == "scene":
        if msg["settings"].get("level", 0) > 3:
            send({"ok": False, "kind": "settings", "error": "settings.misbehaving.level: must be at most 3"})
            continue
        balls = msg["scene"]["balls"]
        n = balls["n"]
        rotation = msg["scene"].get("rotation", False)
        send({"ok": True, "settings": {"level": msg["settings"].get("level", 0), "mode": mode}})
    else:
        if msg["op"] == "step":
            steps += 1
        if steps == 3:
            if mode == "crash":
                sys.stderr.write("Traceback: the misbehaving engine fell over\n")
                sys.stderr.flush()
                sys.exit(3)
            if mode == "hang":
                time.sleep(3600)
            if mode == "garbage":
                out.write(b"this is not json\n")
                out.flush()
                continue
            if mode == "short-block":
                send({"ok": True, "step_s": 0, "state": {"n": n, "t": 0, "fields": ["id", "x", "y", "vx", "vy"]}}, b"\0" * 8)
                out.close()
                sys.exit(0)
            if mode == "bad-ids":
                block = array.array("d", [0.0] * n)  # every ball called 0
                for c in ("x", "y", "vx", "vy"):
                    block.extend(balls[c])
                send({"ok": True, "step_s": 0, "state": {"n": n, "t": 0, "fields": ["id", "x", "y", "vx", "vy"]}}, block.tobytes())
                continue
            if mode == "error":
                send({"ok": False, "error": "the solver lost track of ball 7"})
                continue
        block = array.array("d", range(n))
        for c in ("x", "y"):
            block.extend(balls[c])
        block.extend([0.0] * (2 * n))  # nothing moves
        fields = ["id", "x", "y", "vx", "vy"]
        if rotation:
            if mode != "no-w" or steps < 3:
                fields.append("w")
                block.extend(balls["w"])
            fields.append("angle")
            block.extend([0.0] * n)
        reply = {"ok": True, "state": {"n": n, "t": 0.0, "fields": fields}}
        if msg["op"] == "step":
            reply["step_s"] = 0.0
        send(reply, block.tobytes())
