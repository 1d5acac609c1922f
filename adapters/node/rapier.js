'use strict';
// `rapier`: Rapier2D (@dimforge/rapier2d-compat, WebAssembly, 32-bit floats) behind ballbench's
// engine process protocol. Scene mapping and both profiles: README.md beside this file.
const fs = require('fs');
const path = require('path');
const { serve, applySettings, wallRects, SettingsError, inertiaLabel } = require('./protocol');

const PACKAGE = '@dimforge/rapier2d-compat';

function installedVersion() {
  const file = path.join(__dirname, 'node_modules', PACKAGE, 'package.json');
  if (!fs.existsSync(file)) throw new Error(`${PACKAGE} is not installed: run \`npm ci\` in adapters/node (scripts/lib.sh does)`);
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

// Every setting, with stock's values read from a fresh World where the engine has a default.
function profile(name, R) {
  const p = new R.World({ x: 0, y: 0 }).integrationParameters;
  const stock = {
    solver_iterations: p.numSolverIterations,             // numSolverIterations (4)
    internal_pgs_iterations: p.numInternalPgsIterations,  // per solver iteration (1)
    allowed_linear_error: p.normalizedAllowedLinearError, // overlap left uncorrected (m, lengthUnit 1)
    prediction_distance: p.normalizedPredictionDistance,  // predictive contacts start this far apart (m)
    contact_natural_frequency: 30,                        // soft-contact stiffness (Hz): Rapier's default
    ccd: false,                                           // RigidBodyDesc.setCcdEnabled
    max_ccd_substeps: p.maxCcdSubsteps,
    restitution_combine: 'average',                       // Rapier's default rule
    allow_sleep: false,                                   // every engine runs awake unless asked
  };
  if (name === 'stock') return stock;
  if (name === 'tuned')
    return Object.assign(stock, {
      solver_iterations: 8,            // the user guide: more iterations for more accurate contacts
      allowed_linear_error: 0.0001,    // 0.1 mm instead of 5 mm of overlap left alone
      ccd: true,                       // fast balls cannot pass through walls or each other
      restitution_combine: 'max',      // as Box2D: the larger coefficient (every collider has the scene's)
    });
  throw new Error(`unknown profile '${name}'`);
}

const RULES = { average: 'Average', min: 'Min', multiply: 'Multiply', max: 'Max' };

let R = null;  // the module, initialised on the first scene (its WebAssembly takes ~0.3 s)

async function load(scene, profileName, overrides) {
  if (!R) {
    R = require(PACKAGE);
    await R.init();
  }
  const s = applySettings('rapier', profile(profileName, R), overrides);
  if (!(s.restitution_combine in RULES)) throw new SettingsError(
      `settings.rapier.restitution_combine: '${s.restitution_combine}' is not one of: ${Object.keys(RULES).join(', ')}`);
  if (!(s.solver_iterations >= 1)) throw new SettingsError('settings.rapier.solver_iterations: must be >= 1');
  const rule = R.CoefficientCombineRule[RULES[s.restitution_combine]];
  const world = new R.World({ x: scene.gravity[0], y: scene.gravity[1] });
  world.timestep = scene.dt;
  const ip = world.integrationParameters;
  world.numSolverIterations = s.solver_iterations;
  world.numInternalPgsIterations = s.internal_pgs_iterations;
  world.maxCcdSubsteps = s.max_ccd_substeps;
  ip.normalizedAllowedLinearError = s.allowed_linear_error;
  ip.normalizedPredictionDistance = s.prediction_distance;
  ip.contact_natural_frequency = s.contact_natural_frequency;
  // Every collider, walls included, gets the scene's e and mu, so any rule but multiply combines
  // two of them into the scene's value; friction combines by Rapier's default (average).
  const e = scene.restitution, mu = scene.friction;
  let wall = null;
  if (scene.container.kind === 'box') {
    wall = wallRects(scene.container);
    const ground = world.createRigidBody(R.RigidBodyDesc.fixed());
    for (const [cx, cy, hx, hy] of wall.rects)
      world.createCollider(
          R.ColliderDesc.cuboid(hx, hy).setTranslation(cx, cy).setRestitution(e).setFriction(mu).setRestitutionCombineRule(rule),
          ground);
  }
  const b = scene.balls, bodies = [], k = scene.inertia_factor;
  for (let i = 0; i < b.n; ++i) {
    const body = world.createRigidBody(R.RigidBodyDesc.dynamic()
                                            .setTranslation(b.x[i], b.y[i])
                                            .setLinvel(b.vx[i], b.vy[i])
                                            .setAngvel(b.w ? b.w[i] : 0)
                                            .setCcdEnabled(s.ccd)
                                            .setCanSleep(s.allow_sleep));
    const r = b.radius[i], m = b.mass[i];
    // The collider's mass properties set outright, not from a density: mass m, moment k m r^2
    // about its centre (a disc: k = 1/2).
    world.createCollider(R.ColliderDesc.ball(r).setMassProperties(m, { x: 0, y: 0 }, k * m * r * r)
                             .setRestitution(e).setFriction(mu).setRestitutionCombineRule(rule), body);
    bodies.push(body);
  }
  // Rapier's rotation() is an angle in (-pi, pi]; the state's accumulates from 0, so each read
  // unwraps it against the last (exact while a ball turns less than half a turn between reads:
  // the harness reads after every step).
  const angles = new Float64Array(b.n);
  const p = world.integrationParameters;
  return {
    n: b.n,
    t: 0,
    step() { world.step(); },
    close() { world.free(); },
    read(x, y, vx, vy, w, angle) {
      for (let i = 0; i < bodies.length; ++i) {
        const pos = bodies[i].translation(), v = bodies[i].linvel();
        x[i] = pos.x, y[i] = pos.y, vx[i] = v.x, vy[i] = v.y;
      }
      if (w)
        for (let i = 0; i < bodies.length; ++i) {
          w[i] = bodies[i].angvel();
          const turn = bodies[i].rotation() - angles[i];
          angles[i] += turn - 2 * Math.PI * Math.round(turn / (2 * Math.PI));
          angle[i] = angles[i];
        }
    },
    settings: Object.assign({}, s, {
      derived: {
        real: 'float32',
        timestep: world.timestep,  // the scene's dt as Rapier holds it (f32)
        contact_erp: p.contact_erp,
        length_unit: p.lengthUnit,
        wall_half_thickness: wall ? wall.halfThickness : null,
        restitution_per_collider: e,
        friction_per_collider: mu,
        friction_combine: 'average',
        moment_of_inertia: inertiaLabel(scene),
      },
    }),
  };
}

serve({
  hello() {
    return {
      name: 'rapier',
      version: installedVersion(),
      summary: 'Rapier2D (WebAssembly, float, soft contacts); tuned: CCD, 8 iterations, 0.1 mm allowed error',
      limits: 'float32 (WebAssembly build); stock has no CCD: fast balls can cross walls and each other; soft contacts '
          + '(30 Hz) leave overlap up to allowed_linear_error (stock 5 mm) and push it out over steps; runs in a Node '
          + 'process: engine_s includes the pipe, engine_process_s is Rapier\'s own step',
      capabilities: {
        open_space: true, gravity: true, per_ball_radius: true, per_ball_mass: true, any_restitution: true,
        friction: true, continuous_collision: false, deterministic: true,
      },
      profiles: ['tuned', 'stock'],
      settings_keys: ['solver_iterations', 'internal_pgs_iterations', 'allowed_linear_error', 'prediction_distance',
        'contact_natural_frequency', 'ccd', 'max_ccd_substeps', 'restitution_combine', 'allow_sleep'],
      sweep_knobs: [{ key: 'solver_iterations', values: [2, 4, 8, 16] }, { key: 'ccd', values: [false, true] }],
      // Not in its API docs; measured: a free ball at 1000 m/s leaves its first step at 400 m/s, at
      // any step and radius (tests/test_process_engine.cpp holds it to that).
      speed_cap: { m_per_s: 400, what: 'its speed limit (undocumented, measured)' },
    };
  },
  load,
});
