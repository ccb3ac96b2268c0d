// The frontier of a region-growing traversal of a closed triangle mesh, shared by the link's mesh
// encoder and decoder (mesh-link.js) so that both walk the same way: the region grows one triangle at a
// time across a gate edge, and its boundary is kept as loops of directed edges.
//
// Each node is a directed edge (from -> to) of a visited triangle whose other side is not visited yet,
// with that triangle's third vertex (opposite, for the parallelogram prediction). next/prev go around a
// loop so that the region lies on the left. A loop's nodes around a vertex that the region touches twice
// are kept apart: next(n) is the edge leaving to(n) across the same unvisited gap, which is what makes a
// joined vertex name one place on the frontier.
//
// The triangle across the gate (a -> b) has a tip c. Either c is new (the region grows a vertex), or c is
// on the frontier: on the gate's own loop (k nodes further on, the loop splits in two), or on a loop
// waiting on the stack (the two loops merge: the mesh has a handle). A loop of two nodes is an edge
// whose both sides are now visited: it is dropped. A loop closes when its last triangle is added.

export class Frontier {
  constructor(capacity) {
    this.from = new Int32Array(capacity);
    this.to = new Int32Array(capacity);
    this.opposite = new Int32Array(capacity);
    this.next = new Int32Array(capacity);
    this.prev = new Int32Array(capacity);
    this.count = 0;
    this.waiting = []; // loops set aside after a split: { gate, length }
    this.loop = null; // the loop being grown: { gate, length }; null between components
    this.walked = 0; // steps taken along loops (the decoder bounds it: a hostile link cannot stall the page)
  }

  node(from, to, opposite) {
    if (this.count >= this.from.length) throw new Error('too many edges');
    const n = this.count++;
    this.from[n] = from;
    this.to[n] = to;
    this.opposite[n] = opposite;
    return n;
  }

  link(a, b) {
    this.next[a] = b;
    this.prev[b] = a;
  }

  // The first triangle (a, b, c) of a component.
  seed(a, b, c) {
    const n0 = this.node(a, b, c);
    const n1 = this.node(b, c, a);
    const n2 = this.node(c, a, b);
    this.link(n0, n1);
    this.link(n1, n2);
    this.link(n2, n0);
    this.loop = { gate: n0, length: 3 };
  }

  // The node `steps` along a loop from node n (negative: backwards).
  walk(n, steps) {
    this.walked += Math.abs(steps);
    for (let i = 0; i < steps; i++) n = this.next[n];
    for (let i = 0; i > steps; i--) n = this.prev[n];
    return n;
  }

  // Signed offsets along a loop of `length` nodes, the shorter way round.
  static shorter(k, length) {
    return k <= length / 2 ? k : k - length;
  }

  // The triangle across the gate, with a new vertex c as its tip.
  grow(c) {
    const g = this.loop.gate;
    const a = this.from[g];
    const b = this.to[g];
    const left = this.node(a, c, b);
    const right = this.node(c, b, a);
    this.link(this.prev[g], left);
    this.link(right, this.next[g]);
    this.link(left, right);
    this.loop.length += 1;
    this.loop.gate = right; // around b first: the region grows in a spiral, joins stay next to the gate
  }

  // The triangle across the gate, with its tip the vertex where node m ends. m is k nodes after the gate
  // on the gate's loop (depth < 0), or on the waiting loop `depth` from the top of the stack.
  join(m, k, depth) {
    const g = this.loop.gate;
    const a = this.from[g];
    const b = this.to[g];
    const c = this.to[m];
    const left = this.node(a, c, b);
    const right = this.node(c, b, a);
    const before = this.prev[g];
    const after = this.next[g];
    this.link(before, left);
    this.link(left, this.next[m]);
    this.link(m, right);
    this.link(right, after);
    if (depth >= 0) {
      // Two loops become one: the region now goes round a handle.
      const [other] = this.waiting.splice(this.waiting.length - 1 - depth, 1);
      this.loop = { gate: right, length: this.loop.length + other.length + 1 };
      return;
    }
    const rightLoop = k + 1 > 2 ? { gate: right, length: k + 1 } : null;
    const leftLoop = this.loop.length - k > 2 ? { gate: left, length: this.loop.length - k } : null;
    if (rightLoop && leftLoop) this.waiting.push(leftLoop);
    this.loop = rightLoop ?? leftLoop ?? this.waiting.pop() ?? null;
  }
}
