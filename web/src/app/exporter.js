// Downloads: the cut files and printable tiles (made by the solver in the worker, wasm/src/export), the
// pattern, the inflated shape (three.js exporters) and pictures of the panes. Every export reports what it
// wrote, or why it could not, in the designer's words.
import { Mesh, MeshStandardMaterial, BufferGeometry, BufferAttribute } from 'three';
import { OBJExporter } from 'three/addons/exporters/OBJExporter.js';
import { STLExporter } from 'three/addons/exporters/STLExporter.js';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { Op } from '../worker/protocol.js';
import { download } from './download.js';
import { exportOptions } from './fabrication.js';

export class Exporter {
  // app: the App (design, patterns, panes, client, messages, viewport)
  constructor(app, viewport) {
    this.app = app;
    this.viewport = viewport;
  }

  // The design's name, safe in a file name.
  baseName() {
    return this.app.fileBaseName().replace(/[^\w.-]+/g, '-');
  }

  async run(kind) {
    try {
      if (['svg', 'dxf', 'pdf-a4', 'pdf-letter'].includes(kind)) return await this.cutFiles(kind);
      if (kind === 'pattern') return this.pattern();
      if (['obj', 'stl', 'glb'].includes(kind)) return await this.inflated(kind);
      if (kind.startsWith('png-')) return await this.picture(kind.slice(4));
      throw new Error(`unknown export ${kind}`);
    } catch (error) {
      this.app.messages.show('error', `The export did not work: ${error.message}`);
      return null;
    }
  }

  currentPattern() {
    const text = this.app.store.shown.patternText;
    if (!text) throw new Error('there are no panels yet. Draw seams that cut the target into panels, or open a pattern.');
    return text;
  }

  async cutFiles(kind) {
    const paper = kind === 'pdf-letter' ? 'letter' : 'a4';
    const options = exportOptions(this.app.design.fabrication, { paper, title: `${this.baseName()} (Billow)` });
    const result = await this.app.client.request(Op.exportPattern, { patternText: this.currentPattern(), options });
    const name = this.baseName();
    if (kind === 'svg') download(result.svg, `${name}-pattern.svg`, 'image/svg+xml');
    else if (kind === 'dxf') download(result.dxf, `${name}-pattern.dxf`, 'application/dxf');
    else download(result.pdf, `${name}-pattern-${paper}.pdf`, 'application/pdf');
    this.app.messages.show('notice', `Exported the pattern (${result.statistics.panels.length} panels) at true scale.`);
    return result;
  }

  pattern() {
    download(this.currentPattern(), `${this.baseName()}.pattern.json`, 'application/json');
    return true;
  }

  // The outer surface of the inflated shape as one mesh, in meters.
  inflatedMesh() {
    const shape = this.app.store.shown.inflated;
    if (!shape) throw new Error('nothing is inflated yet.');
    const faces = [];
    for (let f = 0; f < shape.outer.length; f++) if (shape.outer[f]) faces.push(shape.triangles[3 * f], shape.triangles[3 * f + 1], shape.triangles[3 * f + 2]);
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(Float32Array.from(shape.positions), 3));
    geometry.setIndex(new BufferAttribute(Uint32Array.from(faces), 1));
    geometry.computeVertexNormals();
    const mesh = new Mesh(geometry, new MeshStandardMaterial({ color: 0x9ec3e6, roughness: 0.35, metalness: 0.15 }));
    mesh.name = `${this.baseName()} inflated`;
    return mesh;
  }

  async inflated(kind) {
    const mesh = this.inflatedMesh();
    const name = `${this.baseName()}-inflated`;
    try {
      if (kind === 'obj') download(new OBJExporter().parse(mesh), `${name}.obj`, 'model/obj');
      else if (kind === 'stl') download(new STLExporter().parse(mesh, { binary: true }), `${name}.stl`, 'model/stl');
      else download(await new GLTFExporter().parseAsync(mesh, { binary: true }), `${name}.glb`, 'model/gltf-binary');
    } finally {
      mesh.geometry.dispose();
      mesh.material.dispose();
    }
    return true;
  }

  // A PNG of one pane as it is on screen (the renderer keeps its drawing buffer).
  async picture(paneName) {
    const pane = document.querySelector(`#pane-${paneName} .pane-body`);
    this.viewport.render();
    const canvas = this.viewport.canvas;
    const box = canvas.getBoundingClientRect();
    const r = pane.getBoundingClientRect();
    const scale = canvas.width / box.width;
    const out = document.createElement('canvas');
    out.width = Math.round(r.width * scale);
    out.height = Math.round(r.height * scale);
    out.getContext('2d').drawImage(canvas, (r.left - box.left) * scale, (r.top - box.top) * scale, out.width, out.height, 0, 0, out.width, out.height);
    const blob = await new Promise((resolve) => out.toBlob(resolve, 'image/png'));
    download(blob, `${this.baseName()}-${paneName}.png`, 'image/png');
    return true;
  }
}
