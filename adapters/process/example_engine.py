#!/usr/bin/env python3
"""A ballbench engine in Python (standard library only): a template for your own.

It speaks the engine process protocol (PROTOCOL.md beside this file), version 3: JSON requests, one
a line, on stdin; JSON replies, one a line, on stdout, a state reply followed by its block of
little-endian doubles (a reply to `steps`, by one block per step). Its physics is the simplest that is right for single contacts: symplectic Euler (velocity
first), walls that mirror a ball back in, and one restitution impulse per approaching overlapping
pair per step. Run it: ballbench run --scene seed-box --engine "process:python3 adapters/process/example_engine.py"
"""
import array
import json
import sys
import time

PROFILES = {"default": {"pair_passes": 1}}  # settings of each profile: every key a user may --set


class SettingsError(Exception):
    """A bad setting: the harness reports it as the user's error."""


class World:
    def __init__(self, scene, settings):
        b = scene["balls"]
        self.n, self.t = b["n"], 0.0
        self.x, self.y, self.vx, self.vy = list(b["x"]), list(b["y"]), list(b["vx"]), list(b["vy"])
        self.r, self.m = b["radius"], b["mass"]
        # No rotation: the handshake declares friction False, so the harness never sends a scene
        # that rotates, and the scene's inertia, rotation and each ball's spin "w" are ignored.
        self.g, self.e = scene["gravity"], scene["restitution"]
        c = scene["container"]
        self.box = (c["min"], c["max"]) if c["kind"] == "box" else None
        self.passes = settings["pair_passes"]

    def step(self, dt):
        gx, gy = self.g
        for i in range(self.n):
            self.vx[i] += gx * dt
            self.vy[i] += gy * dt
            self.x[i] += self.vx[i] * dt
            self.y[i] += self.vy[i] * dt
        for _ in range(self.passes):
            self.collide_pairs()
        if self.box:
            self.walls()

    def collide_pairs(self):
        x, y, vx, vy, r, m, e = self.x, self.y, self.vx, self.vy, self.r, self.m, self.e
        for i in range(self.n):
            for j in range(i + 1, self.n):
                dx, dy = x[j] - x[i], y[j] - y[i]
                d2, rr = dx * dx + dy * dy, r[i] + r[j]
                if d2 >= rr * rr or d2 == 0.0:
                    continue
                d = d2 ** 0.5
                nx, ny = dx / d, dy / d
                vn = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny
                if vn >= 0.0:  # already moving apart
                    continue
                p = -(1.0 + e) * vn / (1.0 / m[i] + 1.0 / m[j])  # impulse along the normal
                vx[i] -= p * nx / m[i]
                vy[i] -= p * ny / m[i]
                vx[j] += p * nx / m[j]
                vy[j] += p * ny / m[j]

    def walls(self):
        (x0, y0), (x1, y1) = self.box
        for i in range(self.n):
            r = self.r[i]
            self.x[i], self.vx[i] = self.mirror(self.x[i], self.vx[i], x0 + r, x1 - r)
            self.y[i], self.vy[i] = self.mirror(self.y[i], self.vy[i], y0 + r, y1 - r)

    def mirror(self, p, v, lo, hi):
        # A centre past a wall is mirrored back by e times its depth, and its velocity reversed.
        if p < lo and v < 0:
            return lo + self.e * (lo - p), -self.e * v
        if p > hi and v > 0:
            return hi - self.e * (p - hi), -self.e * v
        return min(max(p, lo), hi), v

    def state_block(self):
        block = array.array("d", range(self.n))  # ids: scene order
        for column in (self.x, self.y, self.vx, self.vy):
            block.extend(column)
        if sys.byteorder != "little":
            block.byteswap()
        return block.tobytes()


def hello():
    return {"name": "example", "version": "1.0", "summary": "the Python template engine (PROTOCOL.md)",
            "limits": "O(n^2) pairs in pure Python; one impulse per pair per step; no CCD",
            "capabilities": {"friction": False, "continuous_collision": False, "deterministic": True},
            "profiles": list(PROFILES), "settings_keys": list(PROFILES["default"]),
            "state_fields": ["id", "x", "y", "vx", "vy"]}


def load(msg):
    settings = dict(PROFILES[msg["profile"]])
    for key, value in msg.get("settings", {}).items():
        if key not in settings:
            raise SettingsError(f"settings.example.{key}: unknown setting (known: {', '.join(settings)})")
        if not isinstance(value, int) or value < 1:
            raise SettingsError(f"settings.example.{key}: expected a whole number >= 1, got {json.dumps(value)}")
        settings[key] = value
    return World(msg["scene"], settings), settings


def main():
    out = sys.stdout.buffer
    world = None

    def send(reply, block=b""):
        out.write(json.dumps(reply).encode() + b"\n" + block)
        out.flush()

    def send_state(extra):
        state = {"n": world.n, "t": world.t, "fields": ["id", "x", "y", "vx", "vy"]}
        send(dict(ok=True, state=state, **extra), world.state_block())

    def timed_step(dt):
        t0 = time.perf_counter()
        world.step(dt)
        step_s = time.perf_counter() - t0  # the engine's own step, nothing of the pipe
        world.t += dt
        return step_s

    def send_steps(dt, count):
        # Each step's time and state in one reply; a step that fails ends the batch there, the
        # steps before it sent with the error.
        times, ts, blocks, reply = [], [], [], {"ok": True}
        for _ in range(count):
            try:
                times.append(timed_step(dt))
            except Exception as e:
                reply["error"] = f"{type(e).__name__}: {e}"
                break
            ts.append(world.t)
            blocks.append(world.state_block())
        reply.update(step_s=times, state={"n": world.n, "t": ts, "fields": ["id", "x", "y", "vx", "vy"]})
        send(reply, b"".join(blocks))

    for line in sys.stdin.buffer:  # the harness closing stdin ends the engine
        try:
            msg = json.loads(line)
            op = msg.get("op")
            if op == "hello":
                send(dict(ok=True, protocol=3, **hello()))
            elif op == "scene":
                world, settings = load(msg)
                send({"ok": True, "settings": settings})
            elif op == "steps":
                send_steps(msg["dt"], msg["count"])
            elif op == "step":
                step_s = timed_step(msg["dt"])
                send_state({"step_s": step_s}) if msg.get("read", True) else send({"ok": True, "step_s": step_s})
            elif op == "read":
                send_state({})
            else:
                send({"ok": False, "error": f"unknown request {op!r}"})
        except SettingsError as e:
            send({"ok": False, "kind": "settings", "error": str(e)})
        except Exception as e:  # any other failure is this engine's, reported, never a hang
            send({"ok": False, "kind": "engine", "error": f"{type(e).__name__}: {e}"})


if __name__ == "__main__":
    main()
