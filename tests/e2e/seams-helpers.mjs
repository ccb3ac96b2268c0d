// Helpers for seam tests: screen positions of points on the target, in page pixels.
// dirs: unit directions from the target's center; returns the screen point where the ray from the
// center along each direction leaves the surface (found by raycasting from outside), for the pane camera.
export async function surfaceScreenPoints(page, dirs) {
  return page.evaluate((directions) => {
    const pane = window.billow.test.panes.target;
    const mesh = pane.mesh;
    const box = mesh.geometry.boundingBox;
    const center = box.getCenter(new mesh.position.constructor());
    const radius = box.getSize(new mesh.position.constructor()).length();
    const rect = pane.element.getBoundingClientRect();
    return directions.map(([x, y, z]) => {
      const len = Math.hypot(x, y, z);
      const far = center.clone().add(new mesh.position.constructor(x / len, y / len, z / len).multiplyScalar(radius));
      const world = mesh.localToWorld(far.clone());
      const p = world.project(pane.camera);
      // Aim at where the direction's surface point appears: raycast along the view ray through the far point.
      const local = center.clone().add(new mesh.position.constructor(x / len, y / len, z / len));
      const onSurface = mesh.localToWorld(local).project(pane.camera);
      return { x: rect.left + ((onSurface.x + 1) / 2) * rect.width, y: rect.top + ((1 - onSurface.y) / 2) * rect.height, far: p };
    });
  }, dirs);
}

// The screen point of seam `seam`'s traced curve halfway (by sample count) between control points k and k+1.
export async function seamMidScreenPoint(page, seam, k) {
  return page.evaluate(([s, i]) => {
    const t = window.billow.test;
    const pane = t.panes.target;
    const trace = t.seamTraces()[s];
    const from = trace.controlSamples[i];
    const to = trace.controlSamples[i + 1] ?? trace.faces.length;
    const m = Math.round((from + to) / 2);
    const local = new pane.mesh.position.constructor(trace.curve[3 * m], trace.curve[3 * m + 1], trace.curve[3 * m + 2]);
    const p = pane.mesh.localToWorld(local).project(pane.camera);
    const rect = pane.element.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }, [seam, k]);
}

// Click on seam `seam`'s curve between control points k and k+1 while drawing, so the new point snaps to
// it. Hovers first and waits for the cursor's snap colour (a frame may be late under load); recomputes the
// screen point if the view changed meanwhile. Throws with what is under the pointer when it cannot snap.
export async function clickOnSeam(page, seam, k) {
  let p = null;
  for (let attempt = 0; attempt < 3; attempt++) {
    p = await seamMidScreenPoint(page, seam, k);
    await page.mouse.move(p.x, p.y);
    const snapped = await page
      .waitForFunction(() => window.billow.test.panes.target.seams.cursor.material.color.getHexString() === 'd55e00', null, { timeout: 3000 })
      .then(() => true, () => false);
    if (snapped) {
      const before = await page.evaluate(() => window.billow.test.drawnPoints);
      await page.mouse.click(p.x, p.y);
      await page.waitForFunction((n) => window.billow.test.drawnPoints > n, before, { timeout: 5000 });
      return p;
    }
  }
  const under = await page.evaluate(({ x, y }) => {
    const el = document.elementFromPoint(x, y);
    return el ? `${el.tagName.toLowerCase()}${el.id ? '#' + el.id : ''}.${el.className}` : 'nothing';
  }, p);
  throw new Error(`the pointer at (${p.x.toFixed(0)}, ${p.y.toFixed(0)}) does not snap to seam ${seam}; under it: ${under}`);
}
