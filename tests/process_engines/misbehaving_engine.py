#!/usr/bin/env python3
"""A process engine that misbehaves on purpose (tests/test_process_engine.cpp): balls stay put,
and at step 3 it does what argv[1] names. For a scene that rotates its states carry w (each
ball's initial spin) and angle (0), except in mode "no-w", whose states from step 3 on carry no w.
Modes that misbehave elsewhere: "unavailable", "protocol-4", "no-hello", "name-escape" (a name
with an escape code), "name-all", "profiles-twice", "helper" (starts a process that keeps its
stdout, its pid written to argv[2]), "helper-hang" (the same, and hangs at step 3), "helper-session" (the helper in a session of its
own, out of the engine's process group), "helper-exit" (the engine exits at step 3 while its
helper holds its stdout), "spin-step" (its step 3 computes for ever), "float-t" and "float-t-undeclared" (the time summed in
float32, the precision declared or not), "settings-at-scene" (a settings error for every scene),
"error-at-scene" (an engine error for every scene, as a WebAssembly engine out of memory sends),
"unsupported" (refuses every scene as unsupported), "speed-cap-bad" (a speed cap below zero), "minimal" and "minimal-1" (a handshake of the
required fields only, in protocol version 2 or 1). And two that behave but take time: "busy-step"
(every step spends 20 ms of CPU) and "sleep-step" (every step sleeps 20 ms), each reporting its
step's true time. A mode prefixed "batched-" speaks protocol 3 and answers `steps` with each step's
state, at step 3 doing what the rest of its name says: "error" (the batch stops there, with the
error), "crash", "long-step-s", "wrong-t", "bad-ids", "short-count" (one step time too few, no
error), "cumulative-step-s" (each step sleeps 5 ms and reports the whole batch's time, so the
second step of a batch takes their sum past the round trip: step 3, in the batch of steps 2 and 3)
or "none". Mode "pid-log" behaves, and appends its pid to argv[2] as it starts (how many processes
served the runs). Test-only: never in an engines file."""
import array
import json
import struct
import sys
import time

mode = sys.argv[1] if len(sys.argv) > 1 else "none"
batched = mode.startswith("batched-")
out = sys.stdout.buffer


def send(reply, block=b""):
    out.write(json.dumps(reply).encode() + b"\n" + block)
    out.flush()


if mode in ("helper", "helper-hang", "helper-session", "helper-exit"):
    # starts a helper that keeps stdout open, and says its pid in argv[2]
    import subprocess
    helper = subprocess.Popen(["sleep", "600"], start_new_session=(mode == "helper-session"))
    with open(sys.argv[2], "w") as f:
        f.write(str(helper.pid))
if mode == "pid-log":
    import os
    with open(sys.argv[2], "a") as f:
        f.write(f"{os.getpid()}\n")
if mode == "no-hello":
    sys.stderr.write("misbehaving engine: refusing to start\n")
    sys.exit(4)
n, steps, balls, rotation, t = 0, 0, None, False, 0.0
for line in sys.stdin.buffer:
    msg = json.loads(line)
    if msg["op"] == "hello":
        if mode == "unavailable":
            send({"ok": False, "kind": "unavailable", "error": "the frobnicator library is not installed"})
            continue
        name = {"name-escape": "mis\x1b[31mbehaving", "name-all": "all"}.get(mode, "misbehaving")
        hello = {"ok": True, "protocol": 4 if mode == "protocol-4" else 3 if batched else 2, "name": name, "version": "0",
                 "capabilities": {"friction": True}, "profiles": ["default"], "settings_keys": ["level"]}
        if mode == "float-t":
            hello["precision"] = "float"
        if mode == "speed-cap-bad":
            hello["speed_cap"] = {"m_per_s": -1, "what": "a cap below zero"}
        if mode == "profiles-twice":
            hello["profiles"] = ["default", "default"]
        if mode in ("minimal", "minimal-1"):
            hello = {"ok": True, "protocol": 1 if mode == "minimal-1" else 2, "name": name, "version": "0",
                     "capabilities": {}, "profiles": ["default"]}
        send(hello)
    elif msg["op"] == "scene":
        if msg["settings"].get("level", 0) > 3 or mode == "settings-at-scene":
            send({"ok": False, "kind": "settings", "error": "settings.misbehaving.level: must be at most 3"})
            continue
        if mode == "unsupported":
            send({"ok": False, "kind": "unsupported", "error": "misbehaving cannot run walls today"})
            continue
        if mode == "error-at-scene":
            send({"ok": False, "kind": "engine", "error": "memory access out of bounds"})
            continue
        balls = msg["scene"]["balls"]
        n, t, dt = balls["n"], 0.0, msg["scene"]["dt"]
        rotation = msg["scene"].get("rotation", False)
        send({"ok": True, "settings": {"level": msg["settings"].get("level", 0), "mode": mode}})
    elif msg["op"] == "steps":
        began, times, ts, blocks, reply = time.perf_counter(), [], [], [], {"ok": True}
        for _ in range(msg["count"]):
            steps += 1
            t += msg["dt"]
            step_s = 1e-7
            if mode == "batched-cumulative-step-s":
                time.sleep(0.005)
            if steps == 3:
                if mode == "batched-error":
                    reply["error"] = "the solver lost track of ball 7"
                    break
                if mode == "batched-crash":
                    sys.exit(3)
                step_s = 1e5 if mode == "batched-long-step-s" else step_s
            times.append(step_s)
            ts.append(270.0 if steps == 3 and mode == "batched-wrong-t" else t)
            block = array.array("d", [0.0] * n if steps == 3 and mode == "batched-bad-ids" else range(n))
            for c in ("x", "y"):
                block.extend(balls[c])
            block.extend([0.0] * (2 * n))
            if rotation:
                block.extend(balls["w"])
                block.extend([0.0] * n)
            blocks.append(block.tobytes())
        if mode == "batched-short-count" and steps >= 3:
            times.pop()
        if mode == "batched-cumulative-step-s":  # each inside the round trip, two of them past it
            times = [time.perf_counter() - began] * len(times)
        fields = ["id", "x", "y", "vx", "vy"] + (["w", "angle"] if rotation else [])
        reply.update(step_s=times, state={"n": n, "t": ts, "fields": fields})
        send(reply, b"".join(blocks))
    else:
        step_s = 1e-7  # 100 ns, inside any round trip
        if msg["op"] == "step":
            steps += 1
            if mode in ("busy-step", "sleep-step"):
                start, cpu = time.perf_counter(), time.process_time()
                if mode == "sleep-step":
                    time.sleep(0.02)
                while mode == "busy-step" and time.process_time() - cpu < 0.02:
                    pass
                step_s = time.perf_counter() - start
            t += msg["dt"]
            if mode.startswith("float-t"):  # the time kept in float32, as a float engine keeps it
                t = struct.unpack("f", struct.pack("f", t))[0]
        if steps == 3:
            if mode == "crash":
                sys.stderr.write("Traceback: the misbehaving engine fell over\n")
                sys.stderr.flush()
                sys.exit(3)
            if mode in ("hang", "helper-hang"):
                time.sleep(3600)
            while mode == "spin-step":  # a step that computes for ever
                pass
            if mode == "helper-exit":
                sys.stderr.write("misbehaving engine: leaving my helper behind\n")
                sys.stderr.flush()
                sys.exit(0)
            if mode == "garbage":
                out.write(b"this is not json\n")
                out.flush()
                continue
            if mode in ("short-block", "short-block-alive"):
                send({"ok": True, "step_s": 1e-7, "state": {"n": n, "t": t, "fields": ["id", "x", "y", "vx", "vy"]}}, b"\0" * 8)
                if mode == "short-block-alive":
                    time.sleep(3600)
                out.close()
                sys.exit(0)
            if mode == "bad-ids":
                block = array.array("d", [0.0] * n)  # every ball called 0
                for c in ("x", "y", "vx", "vy"):
                    block.extend(balls[c])
                send({"ok": True, "step_s": 1e-7, "state": {"n": n, "t": t, "fields": ["id", "x", "y", "vx", "vy"]}}, block.tobytes())
                continue
            if mode == "error":
                send({"ok": False, "error": "the solver lost track of ball 7"})
                continue
        block = array.array("d", range(n))
        for c in ("x", "y"):
            block.extend(balls[c])
        if mode in ("far", "far-1e150") and steps == 3:
            block[n] = 1e200 if mode == "far" else 1e150  # ball 0's x, for one step (1e200: its square overflows)
        if mode == "wrong-t" and steps == 3:
            t = 270.0
        block.extend([0.0] * (2 * n))  # nothing moves
        fields = ["id", "x", "y", "vx", "vy"]
        if rotation:
            if mode != "no-w" or steps < 3:
                fields.append("w")
                block.extend(balls["w"])
            fields.append("angle")
            block.extend([0.0] * n)
        reply = {"ok": True, "state": {"n": n, "t": t, "fields": fields}}
        if msg["op"] == "step":
            # At step 3 a step time longer than the round trip, or none at all.
            reply["step_s"] = step_s
            if steps == 3 and mode in ("huge-step-s", "long-step-s", "zero-step-s"):
                reply["step_s"] = {"huge-step-s": 1e308, "long-step-s": 1e5, "zero-step-s": 0.0}[mode]
        if mode == "twice" and steps == 3:  # the step answered twice, in one write
            one = json.dumps(reply).encode() + b"\n" + block.tobytes()
            out.write(one + one)
            out.flush()
            continue
        send(reply, block.tobytes())
