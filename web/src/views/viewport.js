// One WebGL renderer for all panes: the canvas lies under the pane grid and each pane is drawn into its
// own rectangle with the scissor test. Rendering is on demand (after input, resize or new content).
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

  requestRender() {
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
    if (canvas.width !== Math.floor(width * renderer.getPixelRatio()) || canvas.height !== Math.floor(height * renderer.getPixelRatio()))
      renderer.setSize(width, height, false);
    const box = canvas.getBoundingClientRect();
    renderer.setScissor(0, 0, width, height);
    renderer.setClearColor(this.pageColor);
    renderer.clear();
    for (const pane of this.panes) {
      const r = pane.element.getBoundingClientRect();
      if (r.width <= 0 || r.height <= 0) continue;
      const left = r.left - box.left;
      const bottom = box.bottom - r.bottom;
      renderer.setViewport(left, bottom, r.width, r.height);
      renderer.setScissor(left, bottom, r.width, r.height);
      renderer.setClearColor(this.clearColor);
      renderer.clear();
      pane.render(renderer, r.width / r.height);
    }
  }
}
