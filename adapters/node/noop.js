'use strict';
// `noop`: a process engine that moves nothing, so its cost per step is the protocol's alone: the
// request, the reply and the state block through the pipes and Node's event loop. bench/ times it
// beside the Node engines, so a reader sees which part of their time is the engine and which the pipe.
// It declares friction, so rotating scenes reach it: their states carry w and angle too (the pipe
// costs more), each ball keeping its initial spin (nothing touches it) and turning by it, angle w t.
const { serve } = require('./protocol');

serve({
  hello() {
    return {
      name: 'noop',
      version: process.versions.node,
      summary: 'no physics: the balls stay where they are (the pipe cost of a Node process engine)',
      limits: 'not an engine: nothing moves; a spinning ball keeps its spin and turns (angle w t)',
      capabilities: {
        open_space: true, gravity: true, per_ball_radius: true, per_ball_mass: true, any_restitution: true,
        friction: true, continuous_collision: false, deterministic: true,
      },
      profiles: ['default'],
      settings_keys: [],
    };
  },
  async load(scene) {
    const b = scene.balls, spin = b.w || new Array(b.n).fill(0);
    return {
      n: b.n,
      t: 0,
      step() {},
      read(x, y, vx, vy, w, angle) {
        x.set(b.x), y.set(b.y), vx.set(b.vx), vy.set(b.vy);
        if (w) {
          w.set(spin);
          for (let i = 0; i < b.n; ++i) angle[i] = spin[i] * this.t;
        }
      },
      settings: {},
    };
  },
});
