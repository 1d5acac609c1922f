'use strict';
// `box2d3`: Box2D v3 (soft step: substeps, soft contacts, relax iterations) as npm's box2d3-wasm
// compiles it to WebAssembly, behind ballbench's engine process protocol. README.md here has its
// scene mapping and profiles.
const fs = require('fs');
const path = require('path');
const { serve, applySettings, wallRects, SettingsError, inertiaLabel } = require('./protocol');
const { Box2d3State } = require('./box2d3_state');

const PACKAGE = 'box2d3-wasm';
// The Box2D commit the pinned package wraps (box2d3-wasm 5.2.0: Box2D main 3a4f0da8, v3.2's API):
// the package carries no version of Box2D's own, so its label names it.
const BOX2D = 'Box2D v3.2, main 3a4f0da8';

function installedVersion() {
  const file = path.join(__dirname, 'node_modules', PACKAGE, 'package.json');
  if (!fs.existsSync(file)) throw new Error(`${PACKAGE} is not installed: run \`npm ci\` in adapters/node (scripts/lib.sh does)`);
  return JSON.parse(fs.readFileSync(file, 'utf8')).version;
}

// Box2D v3's own defaults (b2DefaultWorldDef, b2World_SetContactTuning's values in b2CreateWorld,
// and the 4 substeps its docs give for b2World_Step), read from the module where it holds them.
function profile(name, B) {
  const def = B.b2DefaultWorldDef();
  const stock = {
    substeps: 4,                                         // b2World_Step's subStepCount: "usually 4"
    contact_hertz: def.contactHertz,                     // 30: contact stiffness (Hz), clamped to a quarter of the substep rate
    contact_damping_ratio: def.contactDampingRatio,      // 10
    contact_push_speed: 3,                               // m/s: the fastest overlap is pushed out (contactSpeed)
    restitution_threshold: def.restitutionThreshold,     // 1 m/s: an approach below it does not bounce
    maximum_linear_speed: def.maximumLinearSpeed,        // 400 m/s
    continuous: def.enableContinuous,                    // continuous collision against static walls
    bullets: false,                                      // continuous collision between dynamic bodies
    warm_starting: true,
    allow_sleep: false,                                  // every engine runs awake unless asked
    read_in_place: true,                                 // states read from Box2D's arrays (box2d3_state.js), not its getters
  };
  def.delete();
  if (name === 'stock') return stock;
  // Its docs for balls that bounce and pile: more substeps for stacking accuracy, every approach
  // bounces (threshold 0), and bullets so that fast balls do not cross each other.
  if (name === 'tuned') return Object.assign(stock, { substeps: 8, restitution_threshold: 0, bullets: true });
  throw new Error(`unknown profile '${name}'`);
}

let B = null;

// The module, loaded once: the SIMD build without threads (one core, as every engine here).
async function box2d() {
  if (!B) {
    const { default: factory } = await import(PACKAGE);
    B = await factory({ pthreadCount: 0 });
  }
  return B;
}

function vec(x, y) { return new B.b2Vec2(x, y); }

async function load(scene, profileName, overrides) {
  await box2d();
  const s = applySettings('box2d3', profile(profileName, B), overrides);
  if (!(Number.isInteger(s.substeps) && s.substeps >= 1 && s.substeps <= 64))
    throw new SettingsError('settings.box2d3.substeps: must be a whole number within 1 .. 64');
  for (const key of ['contact_hertz', 'contact_damping_ratio', 'contact_push_speed', 'maximum_linear_speed'])
    if (!(s[key] > 0)) throw new SettingsError(`settings.box2d3.${key}: must be above 0`);
  if (!(s.restitution_threshold >= 0)) throw new SettingsError('settings.box2d3.restitution_threshold: must be >= 0 (m/s)');

  const wd = B.b2DefaultWorldDef();
  wd.gravity = vec(scene.gravity[0], scene.gravity[1]);
  wd.contactHertz = s.contact_hertz;
  wd.contactDampingRatio = s.contact_damping_ratio;
  wd.restitutionThreshold = s.restitution_threshold;
  wd.maximumLinearSpeed = s.maximum_linear_speed;
  wd.enableContinuous = s.continuous;
  wd.enableSleep = s.allow_sleep;
  wd.workerCount = 1;
  const world = B.b2CreateWorld(wd);
  wd.delete();
  B.b2World_SetContactTuning(world, s.contact_hertz, s.contact_damping_ratio, s.contact_push_speed);
  B.b2World_EnableWarmStarting(world, s.warm_starting);

  // Restitution mixes by max and friction by sqrt(a b) (b2MixRestitution, b2MixFriction): every
  // shape gets the scene's e and mu, so every contact has them.
  const e = scene.restitution, mu = scene.friction;
  const shapeDef = (density) => {
    const sd = B.b2DefaultShapeDef();
    sd.density = density;
    const m = sd.material;
    m.friction = mu, m.restitution = e, m.rollingResistance = 0;
    sd.material = m;
    return sd;
  };
  let wall = null;
  if (scene.container.kind === 'box') {
    wall = wallRects(scene.container);
    const bd = B.b2DefaultBodyDef();
    const ground = B.b2CreateBody(world, bd);
    bd.delete();
    const sd = shapeDef(0);
    for (const [cx, cy, hx, hy] of wall.rects) {
      const box = B.b2MakeOffsetBox(hx, hy, vec(cx, cy), B.b2MakeRot(0));
      B.b2CreatePolygonShape(ground, sd, box);
    }
    sd.delete();
  }
  const b = scene.balls, bodies = [], k = scene.inertia_factor;
  for (let i = 0; i < b.n; ++i) {
    const bd = B.b2DefaultBodyDef();
    bd.type = B.b2BodyType.b2_dynamicBody;
    bd.position = vec(b.x[i], b.y[i]);
    bd.linearVelocity = vec(b.vx[i], b.vy[i]);
    bd.angularVelocity = b.w ? b.w[i] : 0;
    bd.isBullet = s.bullets;
    bd.enableSleep = s.allow_sleep;
    const body = B.b2CreateBody(world, bd);
    bd.delete();
    const r = b.radius[i], m = b.mass[i];
    const circle = new B.b2Circle();
    circle.center = vec(0, 0);
    circle.radius = r;
    const sd = shapeDef(m / (Math.PI * r * r));
    B.b2CreateCircleShape(body, sd, circle);
    sd.delete(), circle.delete();
    // The mass data set outright: mass exactly m (not the float density times pi r^2 back) and
    // moment k m r^2 about the centre (a disc: k = 1/2, Box2D's own).
    const md = B.b2Body_GetMassData(body);
    md.mass = m, md.rotationalInertia = k * m * r * r, md.center = vec(0, 0);
    B.b2Body_SetMassData(body, md);
    md.delete();
    bodies.push(body);
  }
  // Box2D's rotation is a (cos, sin) pair, its angle atan2(sin, cos) in (-pi, pi]; the state's
  // accumulates from 0, so each read unwraps it against the last (exact while a ball turns less
  // than half a turn between reads).
  const angles = new Float64Array(b.n);
  // A body that sleeps leaves the arrays the states are read from in place: then the getters only.
  const inPlace = s.read_in_place && !s.allow_sleep;
  const state = new Box2d3State(B, bodies, !!scene.rotation, inPlace);
  const substepRate = s.substeps / scene.dt;
  return {
    n: b.n,
    t: 0,
    state,  // how its states are read (tests)
    step(dt) {
      B.b2World_Step(world, dt, s.substeps);
      state.stepped();
    },
    close() {
      B.b2DestroyWorld(world);
    },
    read(x, y, vx, vy, w, angle) {
      state.read();
      const { position: p, velocity: v } = state.values;
      for (let i = 0; i < bodies.length; ++i) x[i] = p[2 * i], y[i] = p[2 * i + 1], vx[i] = v[2 * i], vy[i] = v[2 * i + 1];
      if (w) {
        const { spin, rotation: q } = state.values;
        for (let i = 0; i < bodies.length; ++i) {
          w[i] = spin[i];
          const turn = Math.atan2(q[2 * i + 1], q[2 * i]) - angles[i];
          angles[i] += turn - 2 * Math.PI * Math.round(turn / (2 * Math.PI));
          angle[i] = angles[i];
        }
      }
    },
    settings: Object.assign({}, s, {
      derived: {
        real: 'float32',
        box2d: BOX2D,
        build: 'WebAssembly with SIMD (box2d3-wasm "deluxe"), no threads',
        // b2PrepareStagesTask: the contact's stiffness is min(contact_hertz, a quarter of the substep rate).
        effective_contact_hertz: Math.min(s.contact_hertz, 0.25 * substepRate),
        substep_rate_hz: substepRate,
        wall_half_thickness: wall ? wall.halfThickness : null,
        restitution_per_shape: e,
        friction_per_shape: mu,
        moment_of_inertia: inertiaLabel(scene),
        state_reads: inPlace ? 'in place from Box2D\'s arrays once found, every 64th read checked against its getters'
          : 'through Box2D\'s getters',
      },
    }),
  };
}

const driver = {
  hello() {
    return {
      name: 'box2d3',
      version: `${installedVersion()} (${BOX2D})`,
      summary: 'Box2D v3 (soft step with substeps, WebAssembly SIMD build); tuned: 8 substeps, no restitution '
          + 'threshold, bullets',
      limits: 'float32; times are the WebAssembly build\'s, not native Box2D v3\'s; soft contacts: overlap is pushed '
          + 'out at up to contact_push_speed (3 m/s) with stiffness contact_hertz (30 Hz, at most a quarter of the '
          + 'substep rate); stock ignores bounces below 1 m/s; runs in a Node process: engine_s includes the pipe, '
          + 'engine_process_s is Box2D\'s own step',
      // Capabilities are per engine, not per profile: stock ignores restitution below its 1 m/s
      // threshold (the conformance's bounce check refutes a claim of any restitution).
      capabilities: {
        open_space: true, gravity: true, per_ball_radius: true, per_ball_mass: true, any_restitution: false,
        friction: true, continuous_collision: true, deterministic: true,
      },
      profiles: ['tuned', 'stock'],
      settings_keys: ['substeps', 'contact_hertz', 'contact_damping_ratio', 'contact_push_speed',
        'restitution_threshold', 'maximum_linear_speed', 'continuous', 'bullets', 'warm_starting', 'allow_sleep',
        'read_in_place'],
      speed_cap: { setting: 'maximum_linear_speed', what: 'b2WorldDef.maximumLinearSpeed' },
      // Contact stiffness first: a pile's overlap is the soft contact's give, which at Box2D's 30 Hz
      // no step takes below 1% of the radius; the stiffest values reach the clamp (a quarter of
      // the substep rate) at coarse steps. A search tries the knobs in this order, and a
      // configuration it finds early bounds the cost of the rest.
      sweep_knobs: [
        { key: 'contact_hertz', values: [30, 120, 480, 1920] },
        { key: 'substeps', values: [1, 2, 4, 8, 16] },
        { key: 'contact_damping_ratio', values: [1, 10] },
        { key: 'contact_push_speed', values: [1, 3, 10] },
        { key: 'restitution_threshold', values: [0, 1] },
        { key: 'bullets', values: [false, true] },
        { key: 'continuous', values: [false, true] },
      ],
    };
  },
  load,
};

// Run as an engine process; required (tests/box2d3_state_test.js), its load() alone.
if (require.main === module) serve(driver);
module.exports = { load };
