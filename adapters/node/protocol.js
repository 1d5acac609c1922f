'use strict';
// The engine's side of ballbench's engine process protocol (adapters/process/PROTOCOL.md), shared
// by the drivers here: JSON requests, one a line, on stdin; JSON replies, one a line, on stdout,
// each state reply followed by its block of little-endian doubles. Nothing else may be written to
// stdout, so console.log is sent to stderr, which the harness keeps for its error messages.
console.log = console.info = console.warn = console.error;

const PROTOCOL = 3;

// A bad setting: the user's error, reported as such by the harness.
class SettingsError extends Error {}

// One write per reply: each write to the pipe wakes the harness, and a reply in two writes costs
// two wake-ups. Corked, the line and the block leave in one system call without being copied
// together (a batch's block is megabytes).
function send(reply, block) {
  const line = Buffer.from(JSON.stringify(reply) + '\n');
  if (!block) return process.stdout.write(line);
  process.stdout.cork();
  process.stdout.write(line);
  process.stdout.write(block);
  process.stdout.uncork();
}

// The blocks of a batch's states, kept from one batch to the next: a new one per batch costs its
// pages' first touch and the collector's time. Written to the pipe before the next batch begins
// (Node writes to a pipe synchronously on Linux); one still queued is never overwritten.
let blocks = new Float64Array(0);
function blockSpace(doubles) {
  if (blocks.length < doubles || process.stdout.writableLength > 0) blocks = new Float64Array(doubles);
  return blocks.subarray(0, doubles);
}

// Settings of a profile with the overrides applied; each override must exist and keep the type.
function applySettings(engine, defaults, overrides) {
  const out = Object.assign({}, defaults);
  for (const [key, value] of Object.entries(overrides || {})) {
    if (!(key in defaults))
      throw new SettingsError(`settings.${engine}.${key}: unknown setting (known: ${Object.keys(defaults).join(', ')})`);
    if (typeof value !== typeof defaults[key])
      throw new SettingsError(`settings.${engine}.${key}: expected a ${typeof defaults[key]}, got ${JSON.stringify(value)}`);
    if (typeof value === 'number' && !Number.isFinite(value))
      throw new SettingsError(`settings.${engine}.${key}: must be finite`);
    out[key] = value;
  }
  return out;
}

const FIELDS = ['id', 'x', 'y', 'vx', 'vy'];
const ROTATION_FIELDS = ['id', 'x', 'y', 'vx', 'vy', 'w', 'angle'];

// The state block: n ids, then n x, n y, n vx, n vy (doubles, little-endian: the machine's order),
// and for a scene that rotates (scene.rotation) n w (rad/s) and n angles (rad) after them.
function fieldsOf(world) { return world.rotation ? ROTATION_FIELDS : FIELDS; }

function writeState(world, block) {
  const n = world.n;
  for (let i = 0; i < n; ++i) block[i] = i;  // bodies are kept in scene order
  const col = (k) => block.subarray(k * n, (k + 1) * n);
  if (world.rotation) world.read(col(1), col(2), col(3), col(4), col(5), col(6));
  else world.read(col(1), col(2), col(3), col(4));
}

const bytesOf = (a) => Buffer.from(a.buffer, a.byteOffset, a.byteLength);

function stateReply(world, extra) {
  const block = new Float64Array(fieldsOf(world).length * world.n);
  writeState(world, block);
  return [Object.assign({ ok: true }, extra, { state: { n: world.n, t: world.t, fields: fieldsOf(world) } }), bytesOf(block)];
}

// One step of the world, timed by the engine's clock around its step call alone (s).
function timedStep(world, dt) {
  const t0 = process.hrtime.bigint();
  world.step(dt);
  const stepS = Number(process.hrtime.bigint() - t0) * 1e-9;
  world.t += dt;
  return stepS;
}

// `count` steps, each one's time and state, in one reply: one round trip of the pipe for them all.
// A step that throws ends the batch there; the steps before it are sent, with the error.
function batchReply(world, dt, count) {
  if (!(Number.isInteger(count) && count >= 1)) throw new Error(`'count' is ${JSON.stringify(count)}, not a whole number >= 1`);
  const size = fieldsOf(world).length * world.n, space = blockSpace(count * size);
  const times = [], ts = [];
  const reply = { ok: true, step_s: times, state: { n: world.n, t: ts, fields: fieldsOf(world) } };
  for (let k = 0; k < count; ++k) {
    try {
      times.push(timedStep(world, dt));
    } catch (e) {
      reply.error = e.message || String(e);
      break;
    }
    ts.push(world.t);
    writeState(world, space.subarray(k * size, (k + 1) * size));
  }
  return [reply, bytesOf(space.subarray(0, times.length * size))];
}

// The moment of inertia a scene asks for, for the settings: 'k m r^2 (disk, k = 0.5)'.
function inertiaLabel(scene) {
  return `k m r^2 (${scene.inertia}, k = ${scene.inertia_factor})`;
}

// driver: { hello(): handshake fields, or throws (unavailable); async load(scene, profile,
// settings): a world { n, t, rotation, step(dt), read(x, y, vx, vy[, w, angle]), settings,
// close() (optional) } }. A world is closed before the next scene replaces it: an engine in
// WebAssembly frees its memory only when asked (Box2D v3 holds at most 128 worlds at once).
// `rotation` is the scene's (friction or spin): read then fills the angular velocities and angles.
function serve(driver) {
  let world = null;
  const handle = async (msg) => {
    switch (msg.op) {
      case 'hello': {
        let info;
        try {
          info = driver.hello();
        } catch (e) {
          return send({ ok: false, kind: 'unavailable', error: e.message });
        }
        // The columns it may send: w and angle only for a scene that rotates, which an engine
        // without friction is never sent.
        const fields = info.capabilities && info.capabilities.friction === false ? FIELDS : ROTATION_FIELDS;
        return send(Object.assign({ ok: true, protocol: PROTOCOL, state_fields: fields }, info));
      }
      case 'scene':
        if (world && world.close) world.close();
        world = null;
        world = await driver.load(msg.scene, msg.profile, msg.settings || {});
        world.rotation = !!msg.scene.rotation;
        return send({ ok: true, settings: world.settings });
      case 'step': {
        if (!world) throw new Error('step before any scene');
        const stepS = timedStep(world, msg.dt);
        if (!msg.read) return send({ ok: true, step_s: stepS });
        return send(...stateReply(world, { step_s: stepS }));
      }
      case 'steps':
        if (!world) throw new Error('steps before any scene');
        return send(...batchReply(world, msg.dt, msg.count));
      case 'read':
        if (!world) throw new Error('read before any scene');
        return send(...stateReply(world, {}));
      default:
        throw new Error(`unknown request '${msg.op}'`);
    }
  };
  let pending = '';
  let queue = Promise.resolve();
  process.stdin.on('data', (chunk) => {
    pending += chunk.toString('utf8');
    let end;
    while ((end = pending.indexOf('\n')) >= 0) {
      const line = pending.slice(0, end);
      pending = pending.slice(end + 1);
      queue = queue.then(async () => {
        let msg;
        try {
          msg = JSON.parse(line);
        } catch (e) {
          return send({ ok: false, error: `request is not JSON: ${e.message}` });
        }
        try {
          await handle(msg);
        } catch (e) {
          send({ ok: false, kind: e instanceof SettingsError ? 'settings' : 'engine', error: e.message || String(e) });
        }
      });
    }
  });
  process.stdin.on('end', () => queue.then(() => process.exit(0)));
}

// Four static walls of half-thickness w around the box, inner faces on its bounds, as the
// Chipmunk and Box2D adapters build them: thick, so a fast ball is pushed back in, not out.
function wallRects(container) {
  const [x0, y0] = container.min, [x1, y1] = container.max;
  const w = Math.max(1, 0.5 * Math.max(x1 - x0, y1 - y0));
  const cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), hx = 0.5 * (x1 - x0) + 2 * w, hy = 0.5 * (y1 - y0) + 2 * w;
  return {
    halfThickness: w,
    rects: [  // centre x, centre y, half width, half height
      [cx, y0 - w, hx, w], [cx, y1 + w, hx, w], [x0 - w, cy, w, hy], [x1 + w, cy, w, hy],
    ],
  };
}

module.exports = { serve, applySettings, SettingsError, wallRects, inertiaLabel };
