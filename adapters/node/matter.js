'use strict';
// `matter`: matter.js (pure JavaScript, double precision, circles as polygons) behind ballbench's
// engine process protocol. Scene mapping, units and both profiles: README.md beside this file.
const fs = require('fs');
const path = require('path');
const { serve, applySettings, wallRects, SettingsError, inertiaLabel } = require('./protocol');

const PACKAGE = 'matter-js';

function installedVersion() {
  const file = path.join(__dirname, 'node_modules', PACKAGE, 'package.json');
  if (!fs.existsSync(file)) throw new Error(`${PACKAGE} is not installed: run \`npm ci\` in adapters/node (scripts/lib.sh does)`);
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

function profile(name, M) {
  const engine = M.Engine.create();
  const body = M.Body.create({});
  const stock = {
    length_scale: 100,                              // matter units per metre: its thresholds are tuned for pixels
    position_iterations: engine.positionIterations, // 6
    velocity_iterations: engine.velocityIterations, // 4
    slop: body.slop,                                // overlap left alone (units): 0.05
    resting_threshold: moduleDefaults.restingThresh, // approach below it (units per 1/60 s) does not bounce: 2
    circle_max_sides: 25,                           // Bodies.circle's default: sides = min(this, radius in units)
    allow_sleep: false,                             // matter's default (enableSleeping false)
    lock_rotation_without_friction: false,          // inertia Infinity when the scene has no friction
  };
  if (name === 'stock') return stock;
  if (name === 'tuned')
    return Object.assign(stock, {
      position_iterations: 20,  // the docs: more iterations, more accurate contacts
      velocity_iterations: 20,
      slop: 0.01,               // 0.1 mm at 100 units per metre
      resting_threshold: 0,     // every approaching contact bounces (as Box2D's tuned threshold 0)
      // The maintainer's advice for elastic circles (matter-js issues 256, 361): without friction a
      // disc's spin does not matter, but a polygon's off-centre contacts spin it, taking energy.
      lock_rotation_without_friction: true,
      circle_max_sides: 100,    // rounder balls, with length_scale 1000: a 0.1 m ball gets 100 sides
      length_scale: 1000,
      slop: 0.1,                // 0.1 mm at 1000 units per metre
    });
  throw new Error(`unknown profile '${name}'`);
}

let M = null;
let moduleDefaults = null;  // module-wide constants as shipped, read before any world changes them

async function load(scene, profileName, overrides) {
  if (!M) {
    M = require(PACKAGE);
    moduleDefaults = { restingThresh: M.Resolver._restingThresh };
  }
  const s = applySettings('matter', profile(profileName, M), overrides);
  for (const key of ['length_scale', 'position_iterations', 'velocity_iterations', 'circle_max_sides'])
    if (!(s[key] > 0)) throw new SettingsError(`settings.matter.${key}: must be > 0`);
  if (!(s.slop >= 0) || !(s.resting_threshold >= 0))
    throw new SettingsError('settings.matter.slop and resting_threshold: must be >= 0');
  const L = s.length_scale, dtMs = scene.dt * 1000;
  M.Resolver._restingThresh = s.resting_threshold;  // a module-wide constant: one world per process
  // matter applies gravity as a force, g * scale per unit mass, and integrates with the step in
  // ms: the displacement per step grows by g * scale * dtMs^2 units, which is g dt^2 L when scale
  // is L * 1e-6.
  const engine = M.Engine.create({
    positionIterations: s.position_iterations,
    velocityIterations: s.velocity_iterations,
    enableSleeping: s.allow_sleep,
    gravity: { x: scene.gravity[0], y: scene.gravity[1], scale: L * 1e-6 },
  });
  // Every body gets the scene's e (pairs take the larger) and mu (pairs take the smaller), so
  // each contact uses the scene's values; no air friction (matter's default is 0.01 per step).
  const e = scene.restitution, mu = scene.friction, k = scene.inertia_factor;
  const locked = s.lock_rotation_without_friction && mu === 0;  // no contact can change a spin
  const common = { restitution: e, friction: mu, frictionStatic: 1, frictionAir: 0, slop: s.slop };
  const bodies = [];
  let wall = null;
  if (scene.container.kind === 'box') {
    wall = wallRects(scene.container);
    for (const [cx, cy, hx, hy] of wall.rects)
      M.Composite.add(engine.world, M.Bodies.rectangle(cx * L, cy * L, 2 * hx * L, 2 * hy * L, Object.assign({ isStatic: true }, common)));
  }
  const b = scene.balls;
  for (let i = 0; i < b.n; ++i) {
    const r = b.radius[i], m = b.mass[i];
    const body = M.Bodies.circle(b.x[i] * L, b.y[i] * L, r * L, Object.assign({}, common), s.circle_max_sides);
    M.Body.setMass(body, m);
    // The scene's k m r^2 (a disc: k = 1/2; in units: r is r L), not matter's 4x polygon estimate;
    // or, frictionless in tuned, an infinite moment: no contact changes the spin (see the profile).
    M.Body.setInertia(body, locked ? Infinity : k * m * r * r * L * L);
    // Velocity is the displacement per step: position - positionPrev, in units per step of dtMs.
    body.deltaTime = dtMs;
    body.positionPrev.x = body.position.x - b.vx[i] * scene.dt * L;
    body.positionPrev.y = body.position.y - b.vy[i] * scene.dt * L;
    body.velocity.x = b.vx[i] * scene.dt * L, body.velocity.y = b.vy[i] * scene.dt * L;
    // Angular velocity likewise: angle - anglePrev per step, w dt (an angle needs no scaling).
    const w = b.w ? b.w[i] : 0;
    body.anglePrev = body.angle - w * scene.dt;
    body.angularVelocity = w * scene.dt, body.angularSpeed = Math.abs(body.angularVelocity);
    bodies.push(body);
  }
  M.Composite.add(engine.world, bodies);
  let lastDt = scene.dt;
  return {
    n: b.n,
    t: 0,
    step(dt) {
      lastDt = dt;
      M.Engine.update(engine, dt * 1000);
    },
    read(x, y, vx, vy, w, angle) {
      const k = 1 / (lastDt * L);
      for (let i = 0; i < bodies.length; ++i) {
        const p = bodies[i].position, q = bodies[i].positionPrev;
        x[i] = p.x / L, y[i] = p.y / L;
        vx[i] = (p.x - q.x) * k, vy[i] = (p.y - q.y) * k;
      }
      if (w)  // counter-clockwise: the scene's axes, y up, are matter's (gravity is the scene's)
        for (let i = 0; i < bodies.length; ++i)
          w[i] = (bodies[i].angle - bodies[i].anglePrev) / lastDt, angle[i] = bodies[i].angle;
    },
    settings: Object.assign({}, s, {
      derived: {
        real: 'float64',
        gravity_scale: L * 1e-6,
        step_ms: dtMs,
        resting_threshold_m_per_s: s.resting_threshold * 60 / L,  // units per 1/60 s -> m/s
        slop_m: s.slop / L,
        circle_sides: bodies.length ? bodies[0].vertices.length : null,
        wall_half_thickness: wall ? wall.halfThickness : null,
        restitution_per_body: e,
        friction_per_body: mu,
        friction_static: 1,
        friction_air: 0,
        moment_of_inertia: locked ? 'Infinity (frictionless: spin unchanged)' : inertiaLabel(scene),
      },
    }),
  };
}

serve({
  hello() {
    return {
      name: 'matter',
      version: installedVersion(),
      summary: 'matter.js (JavaScript, double, balls as polygons, Verlet); tuned: 20/20 iterations, no resting threshold',
      limits: 'double; a ball is a polygon (stock 26 sides at 25 units radius), so contact normals wobble; no CCD; stock '
          + 'ignores restitution below 2 units per 1/60 s (1.2 m/s at 100 units per metre) and leaves 0.05 units of '
          + 'overlap; position correction moves balls without velocity; runs in a Node process: engine_s includes the '
          + 'pipe, engine_process_s is matter\'s own step',
      capabilities: {
        open_space: true, gravity: true, per_ball_radius: true, per_ball_mass: true, any_restitution: false,
        friction: true, continuous_collision: false, deterministic: true,
      },
      profiles: ['tuned', 'stock'],
      settings_keys: ['length_scale', 'position_iterations', 'velocity_iterations', 'slop', 'resting_threshold',
        'circle_max_sides', 'allow_sleep', 'lock_rotation_without_friction'],
      sweep_knobs: [{ key: 'velocity_iterations', values: [4, 10, 20] }, { key: 'position_iterations', values: [6, 20] }],
    };
  },
  load,
});
