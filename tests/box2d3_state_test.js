'use strict';
// box2d3 reads its states in place (adapters/node/box2d3_state.js): on a heap of 300 rough, spinning
// balls it finds Box2D's arrays within the run, every read from then on equals what Box2D's getters
// say at that step, a placement that no longer holds is caught by the next check and ends the run,
// and with read_in_place off it never reads in place. Exit 77 (skipped) where box2d3-wasm is not
// installed.
const assert = require('assert');
const fs = require('fs');
const path = require('path');

if (!fs.existsSync(path.join(__dirname, '..', 'adapters', 'node', 'node_modules', 'box2d3-wasm'))) {
  console.error('box2d3-wasm is not installed (npm ci in adapters/node)');
  process.exit(77);
}
const { load } = require('../adapters/node/box2d3.js');

// 300 balls on a lattice (15 a row, 0.5 m apart) in a 10 m box, each with its own velocity and
// spin, so that no two bodies' values are alike from the first step on.
function scene() {
  const n = 300, b = { n, x: [], y: [], vx: [], vy: [], w: [], radius: [], mass: [] };
  for (let i = 0; i < n; ++i) {
    b.x.push(0.5 + 0.5 * (i % 15) + 0.01 * (i % 7)), b.y.push(0.5 + 0.5 * Math.floor(i / 15));
    b.vx.push(Math.sin(i)), b.vy.push(Math.cos(1.3 * i)), b.w.push(1 + (i % 11));
    b.radius.push(0.2), b.mass.push(1);
  }
  return {
    name: 'spinning-heap', dt: 0.01, gravity: [0, -9.81], restitution: 0.5, friction: 0.5,
    inertia: 'disk', inertia_factor: 0.5, rotation: true,
    container: { kind: 'box', min: [0, 0], max: [10, 12] }, balls: b,
  };
}

const STEPS = 400;

function fields(n) {
  return ['x', 'y', 'vx', 'vy', 'w', 'angle'].map(() => new Float64Array(n));
}

async function main() {
  const s = scene(), n = s.balls.n;
  const world = await load(s, 'stock', {});
  const [x, y, vx, vy, w, angle] = fields(n);
  let found = 0;
  for (let k = 1; k <= STEPS; ++k) {
    world.step(s.dt);
    world.read(x, y, vx, vy, w, angle);
    if (!world.state.where) continue;
    if (!found) found = k;
    // What the getters say now (no step between): the in-place read, value for value.
    world.state.readGetters();
    const { position: p, velocity: v, spin } = world.state.values;
    for (let i = 0; i < n; ++i) {
      assert.strictEqual(x[i], p[2 * i], `x of ball ${i} at step ${k}`);
      assert.strictEqual(y[i], p[2 * i + 1], `y of ball ${i} at step ${k}`);
      assert.strictEqual(vx[i], v[2 * i], `vx of ball ${i} at step ${k}`);
      assert.strictEqual(vy[i], v[2 * i + 1], `vy of ball ${i} at step ${k}`);
      assert.strictEqual(w[i], spin[i], `w of ball ${i} at step ${k}`);
    }
  }
  assert.ok(found > 0, `the arrays were not found in ${STEPS} steps`);

  // A placement one float off: the next check against the getters ends the run.
  const [offset, stride] = world.state.where.position;
  world.state.where.position = [offset + 1, stride];
  assert.throws(() => {
    for (let k = 0; k < 64; ++k) world.step(s.dt), world.read(x, y, vx, vy, w, angle);
  }, /no longer agrees with Box2D's getters/);

  const getters = await load(s, 'stock', { read_in_place: false });
  for (let k = 1; k <= STEPS; ++k) getters.step(s.dt), getters.read(x, y, vx, vy, w, angle);
  assert.strictEqual(getters.state.where, null, 'read in place though read_in_place is false');
  console.log(`box2d3 read ${n} balls in place from step ${found} of ${STEPS}`);
}

main().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
