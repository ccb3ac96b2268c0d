// One WebGL renderer for all panes: the canvas lies under the pane grid and each pane is drawn into its
// own rectangle with the scissor test. Rendering is on demand (after input, resize or new content), and only
// of the panes that changed: the drawing buffer is kept, so an optimization streaming its iterates to the
// inflated pane leaves the target and the pattern as drawn (on a software rasterizer every pane drawn costs
// the CPU the solver needs).
import { WebGLRenderer, Color } from 'three';

// Whether WebGL runs on a software rasterizer, by the renderer's name (Chromium and Firefox expose it).
function softwareRendering() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

export class Viewport {
  constructor(canvas) {
    this.canvas = canvas;
    // No multisampling on a software rasterizer (no GPU: SwiftShader, llvmpipe): there it costs the CPU the
    // solver needs, so the edges stay unsmoothed.
    this.renderer = new WebGLRenderer({ canvas, antialias: !softwareRendering(), preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setScissorTest(true);
    this.panes = [];
    this.scheduled = false;
    this.dirty = new Set(); // the panes to draw at the next frame
    this.all = true; // every pane, and the page between them
    this.drawn = []; // each pane's rectangle in the canvas when last drawn
    this.clearColor = new Color(0xeef1f6); // each pane's background
    this.pageColor = new Color(0xf4f5f7); // between the panes
    new ResizeObserver(() => this.requestRender()).observe(canvas);
  }

  // The theme's colors (CSS color strings); unparsable ones are ignored.
  setColors({ pane, page }) {
    if (pane) this.clearColor.setStyle(pane);
    if (page) this.pageColor.setStyle(page);
    this.requestRender();
  }

  add(pane) {
    this.panes.push(pane);
    new ResizeObserver(() => {
      pane.resize?.();
      this.requestRender();
    }).observe(pane.element);
    this.requestRender();
  }

  // A frame for `pane` (a pane's own content changed) or, without one, for all of them.
  requestRender(pane = null) {
    if (pane) this.dirty.add(pane);
    else this.all = true;
    if (this.scheduled) return;
    this.scheduled = true;
    requestAnimationFrame(() => {
      this.scheduled = false;
      this.render();
    });
  }

  render() {
    const { canvas, renderer } = this;
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (canvas.width !== Math.floor(width * renderer.getPixelRatio()) || canvas.height !== Math.floor(height * renderer.getPixelRatio())) {
      renderer.setSize(width, height, false);
      this.all = true;
    }
    const box = canvas.getBoundingClientRect();
    const rects = this.panes.map((pane) => {
      const r = pane.element.getBoundingClientRect();
      return { left: r.left - box.left, bottom: box.bottom - r.bottom, width: r.width, height: r.height };
    });
    // A pane moved or changed size since it was drawn: all are drawn again, and the page between them.
    const same = (a, b) => b && a.left === b.left && a.bottom === b.bottom && a.width === b.width && a.height === b.height;
    const all = this.all || rects.some((r, i) => !same(r, this.drawn[i]));
    if (all) {
      renderer.setScissor(0, 0, width, height);
      renderer.setClearColor(this.pageColor);
      renderer.clear();
    }
    this.panes.forEach((pane, i) => {
      const r = rects[i];
      if (r.width <= 0 || r.height <= 0 || !(all || this.dirty.has(pane))) return;
      renderer.setViewport(r.left, r.bottom, r.width, r.height);
      renderer.setScissor(r.left, r.bottom, r.width, r.height);
      renderer.setClearColor(this.clearColor);
      renderer.clear();
      pane.render(renderer, r.width / r.height);
    });
    this.drawn = rects;
    this.dirty.clear();
    this.all = false;
  }
}
