'use strict';
// Box2D v3's body states, read in place. Its getters (b2Body_GetPosition and the like) return a new
// object through embind on every call, about 1.5 us per body and quantity: on a pile, more than
// the step. Box2D keeps an awake body's transform (b2BodySim) and velocities (b2BodyState) in
// arrays in the WebAssembly heap, one element per body in creation order while no body sleeps, is
// added or is removed, which never happens in a ballbench run. This reader finds those arrays by
// the getters' own values (every body's, at one stride) and from then on reads the same float32s
// in place.
//
// Nothing is taken on trust: until every quantity is found, and confirmed one step later, it reads
// through the getters; once found, every CHECK_EVERY-th read goes through the getters too and must
// agree value for value, or the run ends with an error (never a state read from the wrong place).
// `inPlace` false reads through the getters always (the box2d3 setting `read_in_place`, or
// `allow_sleep`: a body that sleeps leaves the arrays).

const CHECK_EVERY = 64;
// Finding the arrays scans the heap once per quantity, about 2.7 ns per float32 (11 ms per 16 MB),
// where a getter's call costs about 1.8 us (both measured on pile, the same machine and load): a
// search costs as much as this many getter calls per float32 of the heap. It is tried once the
// getters have made that many calls since the last search, and after a search that found nothing
// twice as many, so searching never costs more than the getters did and a short run never pays for
// it. Counted in calls, not timed: the same run reads the same way on any machine.
const GETTER_CALLS_PER_HEAP_FLOAT = 2.7e-9 / 1.8e-6;
// A quantity whose first value occurs more often than this in the heap cannot be placed yet.
const MAX_CANDIDATES = 64;

// Each quantity: its float32s per body, and how the getters read it for body `id` into `out` at `at`.
const QUANTITIES = {
  position: { dims: 2, get(B, id, out, at) { const p = B.b2Body_GetPosition(id); out[at] = p.x, out[at + 1] = p.y; p.delete(); } },
  velocity: { dims: 2, get(B, id, out, at) { const v = B.b2Body_GetLinearVelocity(id); out[at] = v.x, out[at + 1] = v.y; v.delete(); } },
  spin: { dims: 1, get(B, id, out, at) { out[at] = B.b2Body_GetAngularVelocity(id); } },
  rotation: { dims: 2, get(B, id, out, at) { const q = B.b2Body_GetRotation(id); out[at] = q.c, out[at + 1] = q.s; q.delete(); } },
};

// Where `values` (n bodies of `dims` floats) sit in `heap` at one stride: [offset, stride] pairs in
// floats, for every placement that holds all n bodies.
function placements(heap, values, n, dims) {
  // The first float by the typed array's own indexOf (native: some 20 times a loop's speed here),
  // the others compared where it is.
  const firsts = (i) => {
    const at = [], first = values[i * dims];
    for (let o = heap.indexOf(first); o >= 0 && o + dims <= heap.length; o = heap.indexOf(first, o + 1)) {
      let k = 1;
      while (k < dims && heap[o + k] === values[i * dims + k]) ++k;
      if (k === dims && at.push(o) > MAX_CANDIDATES) return null;
    }
    return at;
  };
  const a = firsts(0), b = n > 1 ? firsts(1) : [];
  if (!a || !b) return [];
  const found = [];
  for (const o of a)
    for (const o1 of (n > 1 ? b : [o + dims])) {
      const stride = o1 - o;
      if (stride < dims || o + stride * (n - 1) + dims > heap.length) continue;
      if (holds(heap, [o, stride], values, n, dims)) found.push([o, stride]);
    }
  return found;
}

// Values a search can place: the first two bodies' differ, and the first's hold no 0 (a body at
// rest, or not yet turned, has zeros the heap is full of).
function distinctive(values, dims) {
  let same = true;
  for (let k = 0; k < dims; ++k) {
    if (values[k] === 0) return false;
    same = same && values.length > dims && values[k] === values[dims + k];
  }
  return !same || values.length === dims;
}

function holds(heap, [offset, stride], values, n, dims) {
  for (let i = 0; i < n; ++i)
    for (let k = 0; k < dims; ++k)
      if (heap[offset + stride * i + k] !== values[i * dims + k]) return false;
  return true;
}

class Box2d3State {
  constructor(B, bodies, rotation, inPlace) {
    this.B = B, this.bodies = bodies, this.n = bodies.length, this.inPlace = inPlace;
    this.names = rotation ? ['position', 'velocity', 'spin', 'rotation'] : ['position', 'velocity'];
    this.values = {};
    for (const q of this.names) this.values[q] = new Float32Array(this.n * QUANTITIES[q].dims);
    this.where = null;       // quantity -> [offset, stride] once found and confirmed
    this.candidates = null;  // quantity -> placements found, to be confirmed after the next step
    this.calls = 0;          // getter calls since the last search
    this.searchAfter = 1;    // a search waits for the getters to cost this many searches
    this.steps = 0, this.stepsAtSearch = -1, this.reads = 0;
    this.view = null;
  }

  stepped() { ++this.steps; }

  // The heap as float32s: a new view after the WebAssembly memory grew.
  heap() {
    const buffer = this.B.HEAPU8.buffer;
    if (!this.view || this.view.buffer !== buffer) this.view = new Float32Array(buffer, 0, buffer.byteLength >> 2);
    return this.view;
  }

  // Fills this.values with the state now.
  read() {
    ++this.reads;
    if (this.where && this.reads % CHECK_EVERY !== 0) return this.readInPlace();
    this.readGetters();
    if (this.where) return this.check();
    if (this.inPlace) this.locate();
  }

  readGetters() {
    const { B, bodies, n } = this;
    for (const q of this.names) {
      const { dims, get } = QUANTITIES[q], out = this.values[q];
      for (let i = 0; i < n; ++i) get(B, bodies[i], out, i * dims);
    }
    this.calls += n * this.names.length;
  }

  readInPlace() {
    const heap = this.heap(), n = this.n;
    for (const q of this.names) {
      const dims = QUANTITIES[q].dims, out = this.values[q], [offset, stride] = this.where[q];
      for (let i = 0; i < n; ++i)
        for (let k = 0; k < dims; ++k) out[i * dims + k] = heap[offset + stride * i + k];
    }
  }

  check() {
    const heap = this.heap();
    for (const q of this.names)
      if (!holds(heap, this.where[q], this.values[q], this.n, QUANTITIES[q].dims))
        throw new Error(`box2d3: the ${q} read in place no longer agrees with Box2D's getters at read ${this.reads} `
            + '(its arrays moved in the heap): set box2d3.read_in_place = false to read through the getters');
  }

  // Searches the heap once the getters have cost enough; confirms a search's placements a step
  // later (a stale copy of the values does not follow the step).
  locate() {
    const heap = this.heap();
    if (this.candidates && this.steps > this.stepsAtSearch) {
      const kept = {};
      for (const q of this.names) {
        const left = this.candidates[q].filter((p) => holds(heap, p, this.values[q], this.n, QUANTITIES[q].dims));
        if (!left.length) return void (this.candidates = null, this.searchAfter *= 2);
        kept[q] = left[0];
      }
      this.where = kept, this.candidates = null;
      return;
    }
    const cost = this.searchAfter * heap.length * this.names.length * GETTER_CALLS_PER_HEAP_FLOAT;
    if (this.candidates || this.calls < cost || this.steps === 0) return;
    if (!this.names.every((q) => distinctive(this.values[q], QUANTITIES[q].dims))) return;
    const found = {};
    for (const q of this.names)
      if (!(found[q] = placements(heap, this.values[q], this.n, QUANTITIES[q].dims)).length) break;
    this.calls = 0;
    if (this.names.every((q) => found[q] && found[q].length)) this.candidates = found, this.stepsAtSearch = this.steps;
    else this.searchAfter *= 2;
  }
}

module.exports = { Box2d3State };
