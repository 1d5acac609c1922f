'use strict';
// `planck`: planck.js (a JavaScript port of Box2D, double precision) behind ballbench's engine
// process protocol. Profiles as the Box2D adapter's (adapters/box2d/README.md): README.md here.
const fs = require('fs');
const path = require('path');
const { serve, applySettings, wallRects, SettingsError, inertiaLabel } = require('./protocol');

const PACKAGE = 'planck';

function installedVersion() {
  const file = path.join(__dirname, 'node_modules', PACKAGE, 'package.json');
  if (!fs.existsSync(file)) throw new Error(`${PACKAGE} is not installed: run \`npm ci\` in adapters/node (scripts/lib.sh does)`);
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

function profile(name, P) {
  const w = new P.World();
  const stock = {
    velocity_iterations: w.m_velocityIterations,        // 8
    position_iterations: w.m_positionIterations,        // 3
    restitution_threshold: moduleDefaults.velocityThreshold, // approach below it does not bounce (m/s): 1
    bullets: false,                                     // CCD between dynamic bodies
    continuous_physics: w.m_continuousPhysics,          // CCD against static walls: on
    warm_starting: w.m_warmStarting,
    allow_sleep: false,                                 // every engine runs awake unless asked
  };
  if (name === 'stock') return stock;
  // As the Box2D adapter's tuned profile: its manual and issues on elastic balls.
  if (name === 'tuned') return Object.assign(stock, { velocity_iterations: 10, position_iterations: 8, restitution_threshold: 0, bullets: true });
  throw new Error(`unknown profile '${name}'`);
}

let P = null;
let moduleDefaults = null;  // module-wide settings as shipped, read before any world changes them

async function load(scene, profileName, overrides) {
  if (!P) {
    P = require(PACKAGE);
    moduleDefaults = { velocityThreshold: P.Settings.velocityThreshold };
  }
  const s = applySettings('planck', profile(profileName, P), overrides);
  if (!(s.velocity_iterations >= 1) || !(s.position_iterations >= 0))
    throw new SettingsError('settings.planck.velocity_iterations/position_iterations: must be >= 1 and >= 0');
  if (!(s.restitution_threshold >= 0)) throw new SettingsError('settings.planck.restitution_threshold: must be >= 0 (m/s)');
  P.Settings.velocityThreshold = s.restitution_threshold;  // module-wide: one world per process
  const world = new P.World({ gravity: { x: scene.gravity[0], y: scene.gravity[1] } });
  world.setContinuousPhysics(s.continuous_physics);
  world.setWarmStarting(s.warm_starting);
  world.setAllowSleeping(s.allow_sleep);
  // Restitution mixes by max and friction by sqrt(a b): every fixture gets the scene's e and mu,
  // so every contact has the scene's values.
  const e = scene.restitution, mu = scene.friction;
  let wall = null;
  if (scene.container.kind === 'box') {
    wall = wallRects(scene.container);
    const ground = world.createBody();
    for (const [cx, cy, hx, hy] of wall.rects)
      ground.createFixture(new P.Box(hx, hy, { x: cx, y: cy }, 0), { restitution: e, friction: mu });
  }
  const b = scene.balls, bodies = [], k = scene.inertia_factor;
  for (let i = 0; i < b.n; ++i) {
    const r = b.radius[i], m = b.mass[i];
    const body = world.createDynamicBody({ position: { x: b.x[i], y: b.y[i] }, linearVelocity: { x: b.vx[i], y: b.vy[i] },
                                           angularVelocity: b.w ? b.w[i] : 0, bullet: s.bullets, allowSleep: s.allow_sleep });
    // A disc of density m / (pi r^2), then the mass data set outright: mass exactly m (not the
    // density times pi r^2 back) and moment k m r^2 about the centre (a disc: k = 1/2, Box2D's own).
    body.createFixture(new P.Circle(r), { density: m / (Math.PI * r * r), restitution: e, friction: mu });
    body.setMassData({ mass: m, center: { x: 0, y: 0 }, I: k * m * r * r });
    bodies.push(body);
  }
  return {
    n: b.n,
    t: 0,
    step(dt) { world.step(dt, s.velocity_iterations, s.position_iterations); },
    read(x, y, vx, vy, w, angle) {
      for (let i = 0; i < bodies.length; ++i) {
        const p = bodies[i].getPosition(), v = bodies[i].getLinearVelocity();
        x[i] = p.x, y[i] = p.y, vx[i] = v.x, vy[i] = v.y;
      }
      if (w)  // planck's angle accumulates from 0 (counter-clockwise), as Box2D's
        for (let i = 0; i < bodies.length; ++i) w[i] = bodies[i].getAngularVelocity(), angle[i] = bodies[i].getAngle();
    },
    settings: Object.assign({}, s, {
      derived: {
        real: 'float64',
        linear_slop: P.Settings.linearSlop,
        max_translation_per_step: P.Settings.maxTranslation,
        baumgarte: P.Settings.baumgarte,
        wall_half_thickness: wall ? wall.halfThickness : null,
        restitution_per_fixture: e,
        friction_per_fixture: mu,
        moment_of_inertia: inertiaLabel(scene),
      },
    }),
  };
}

serve({
  hello() {
    return {
      name: 'planck',
      version: installedVersion(),
      summary: 'planck.js (JavaScript port of Box2D, double); tuned: iterations 10/8, no restitution threshold, bullets',
      limits: 'double; Box2D 2.x\'s solver: stock ignores bounces below 1 m/s, resting contacts sit up to linear slop '
          + '(5 mm) deep; a ball moves at most 2 m per step; runs in a Node process: engine_s includes the pipe, '
          + 'engine_process_s is planck\'s own step',
      capabilities: {
        open_space: true, gravity: true, per_ball_radius: true, per_ball_mass: true, any_restitution: false,
        friction: true, continuous_collision: false, deterministic: true,
      },
      profiles: ['tuned', 'stock'],
      settings_keys: ['velocity_iterations', 'position_iterations', 'restitution_threshold', 'bullets',
        'continuous_physics', 'warm_starting', 'allow_sleep'],
      sweep_knobs: [{ key: 'velocity_iterations', values: [4, 8, 10, 20] }, { key: 'bullets', values: [false, true] }],
      speed_cap: { m_per_step: require(PACKAGE).Settings.maxTranslation, what: 'Settings.maxTranslation (2 m per step)' },
    };
  },
  load,
});
