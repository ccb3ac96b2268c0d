// segmentDistance (web/src/app/geometry.js), the one distance from a point to a segment the pattern pane, the mirror
// twins and the gusset bands measure with, in 2D and 3D, against distances worked by hand.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { segmentDistance } from '../../web/src/app/geometry.js';

test('a point is as far from a segment as from its nearest point, on the pattern (2D) and the target (3D)', () => {
  // Beside the segment, beyond either end, on it, and from a segment that is a point.
  assert.equal(segmentDistance([1, 2], [0, 0], [3, 0]), 2);
  assert.equal(segmentDistance([-3, 4], [0, 0], [3, 0]), 5);
  assert.equal(segmentDistance([6, 4], [0, 0], [3, 0]), 5);
  assert.equal(segmentDistance([2, 0], [0, 0], [3, 0]), 0);
  assert.equal(segmentDistance([1, 1], [4, 5], [4, 5]), 5);
  assert.ok(Math.abs(segmentDistance([1, 1, 1], [0, 0, 0], [2, 2, 2])) < 1e-15);
  assert.ok(Math.abs(segmentDistance([0, 0, 1], [-1, 0, 0], [1, 0, 0]) - 1) < 1e-15);
  assert.ok(Math.abs(segmentDistance([3, 0, 4], [0, 0, 0], [0, 0, 2]) - Math.hypot(3, 2)) < 1e-15);
});
