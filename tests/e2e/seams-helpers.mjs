// Helpers for seam tests: screen positions of points on the target, in page pixels.
// dirs: unit directions from the target's center; returns the screen point where the ray from the
// center along each direction leaves the surface (found by raycasting from outside), for the pane camera.
export async function surfaceScreenPoints(page, dirs) {
  return page.evaluate((directions) => {
    const pane = window.billow.app.panes.target;
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
    const app = window.billow.app;
    const pane = app.panes.target;
    const trace = app.seams.seamTraces()[s];
    const from = trace.controlSamples[i];
    const to = trace.controlSamples[i + 1] ?? trace.faces.length;
    const m = Math.round((from + to) / 2);
    const local = new pane.mesh.position.constructor(trace.curve[3 * m], trace.curve[3 * m + 1], trace.curve[3 * m + 2]);
    const p = pane.mesh.localToWorld(local).project(pane.camera);
    const rect = pane.element.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }, [seam, k]);
}
