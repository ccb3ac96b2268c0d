// The gallery: ready designs and patterns, each with a thumbnail (web/public/gallery/<id>.png, made by
// scripts/make-gallery.mjs) and one line on what it teaches. A design opens with its stored result (its
// optimized panels and their inflated shape, <id>.result.json, made by the same script with the app's own
// pipeline) shown at once, while it is segmented and its panels optimized live; a pattern is inflated.
import { parseDesign } from './design.js';
import { parseStoredResult } from './stored-result.js';
import './gallery.css';
import { dialogHeader } from '../views/dialog-header.js';

// open: { design: file } a billow-design in web/public/gallery (its stored result beside it, <id>.result.json);
// { pattern: id } a solver example pattern (PATTERN_EXAMPLES in pattern-session.js); { patternFile: file } a billow-pattern
// in web/public/gallery.
export const GALLERY_ITEMS = [
  {
    id: 'mylar', title: 'Mylar balloon', thumbnail: 'mylar.png', open: { pattern: 'mylar' },
    teaches: 'Two flat discs sewn at the rim do not make a sphere: they puff into a pillow with wrinkles at the rim.',
  },
  {
    id: 'sphere3', title: 'Sphere, three gores', thumbnail: 'sphere3.png', open: { design: 'sphere3.billow.json' },
    teaches: 'Three meridian seams from pole to pole: the optimizer shapes the gores so the inflated ball is round.',
  },
  {
    id: 'sphere-sliding', title: 'Sphere, sliding seams', thumbnail: 'sphere-sliding.png', open: { design: 'sphere-sliding.billow.json' },
    teaches: 'The same three gores with seams of weight 0: free to slide, they curve into S-shaped strips like a tennis ball\'s, and the ball comes out far rounder.',
  },
  {
    id: 'pillow', title: 'Pillow', thumbnail: 'pillow.png', open: { pattern: 'pillow' },
    teaches: 'Two squares sewn at the edges: the corners pucker and the sides pull in under pressure.',
  },
  {
    id: 'toy', title: 'Penguin toy', thumbnail: 'toy.png', open: { design: 'toy.billow.json' },
    teaches: 'A plush-toy cut: left and right halves sewn along the middle, optimized to bulge into the penguin.',
  },
  {
    id: 'koala', title: 'Koala, a plush toy', thumbnail: 'koala.png', open: { design: 'koala.billow.json' },
    teaches: 'A teddy cut in 18 panels: seams along the middle, down each side through the legs, across the back and the head, and around each ear; narrow panels that follow the body, legs and ears let the inflated toy keep them, where a few wide panels round them off into a plump blob.',
  },
  {
    id: 'fish', title: 'Fish with an internal panel', thumbnail: 'fish.png', open: { design: 'fish.billow.json' },
    teaches: 'An internal panel works only where pressure pulls it tight: this one ties the left and right flank seams together from behind the head to the tail, so the tall, narrow body and tail stay slim instead of puffing round.',
  },
  {
    id: 'star', title: 'Star foil balloon', thumbnail: 'star.png', open: { patternFile: 'star.pattern.json' },
    teaches: 'Two flat stars sealed at the rim: the points stay thin while the middle inflates, with wrinkles at the inner corners.',
  },
];

export function findGalleryItem(id) {
  return GALLERY_ITEMS.find((item) => item.id === id) ?? null;
}

export class Gallery {
  constructor(app, button) {
    this.app = app;
    this.dialog = document.createElement('dialog');
    this.dialog.className = 'gallery';
    const header = dialogHeader(this.dialog, {
      id: 'gallery-title', title: 'Gallery', closeClass: 'gallery-close', closeTitle: 'Close the gallery (Esc)', onClose: () => this.dialog.close(),
    });
    const intro = document.createElement('p');
    intro.className = 'gallery-intro';
    intro.textContent = 'Ready designs and patterns: a design opens with its seams and its optimized panels already inflated, then refines them live; a pattern is inflated as it opens.';
    this.grid = document.createElement('div');
    this.grid.className = 'gallery-grid';
    for (const item of GALLERY_ITEMS) this.grid.append(this.card(item));
    this.dialog.append(header, intro, this.grid);
    // A click on the backdrop (outside the dialog's box) closes it.
    this.dialog.addEventListener('click', (event) => {
      if (event.target === this.dialog) this.dialog.close();
    });
    document.body.append(this.dialog);
    button?.addEventListener('click', () => this.show());
  }

  card(item) {
    const card = document.createElement('button');
    card.type = 'button';
    card.className = 'gallery-card';
    card.dataset.item = item.id;
    card.title = `Open "${item.title}": it replaces the current design (save that first to keep it); ${item.open.design
      ? 'its stored result shows at once and is refined live' : 'it is inflated as it opens'}`;
    const img = document.createElement('img');
    img.src = new URL(`gallery/${item.thumbnail}`, this.app.baseUrl).href;
    img.alt = item.title;
    img.width = 320;
    img.height = 240;
    img.loading = 'lazy';
    const title = document.createElement('span');
    title.className = 'gallery-title';
    title.textContent = item.title;
    const line = document.createElement('span');
    line.className = 'gallery-teaches';
    line.textContent = item.teaches;
    card.append(img, title, line);
    card.addEventListener('click', () => {
      this.dialog.close();
      this.open(item.id);
    });
    return card;
  }

  show() {
    if (!this.dialog.open) this.dialog.showModal();
  }

  // Opens a gallery item by id; resolves when the app has taken it (a design's stored result is then shown
  // and its live optimization under way).
  async open(id) {
    const item = findGalleryItem(id);
    if (!item) return this.app.messages.show('error', `There is no gallery item called "${id}".`);
    if (item.open.pattern) return this.app.patterns.openExample(item.open.pattern);
    const file = item.open.design ?? item.open.patternFile;
    // A design's stored result is fetched with it; without it (offline, stale) the result is made live.
    const storedText = item.open.design ? this.fetchText(resultFileOf(file)).catch(() => null) : null;
    let text;
    try {
      text = await this.fetchText(file);
    } catch {
      return this.app.messages.show('error', `"${item.title}" could not be loaded from the gallery: check the connection and try again.`);
    }
    if (item.open.patternFile) return this.app.patterns.open(item.title, text);
    let design;
    try {
      const parsed = parseDesign(JSON.parse(text));
      for (const w of parsed.warnings) this.app.messages.show('warning', w);
      design = parsed.design;
      if (!design.target.example) throw new Error('its target is not a built-in example.');
    } catch (error) {
      return this.app.messages.show('error', `"${item.title}" cannot be opened: ${error.message}`);
    }
    const stored = parseStoredResult(await storedText);
    return this.app.loadExample(design.target.example, design, { stored });
  }

  async fetchText(file) {
    const response = await fetch(new URL(`gallery/${file}`, this.app.baseUrl));
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    return response.text();
  }
}

// The stored result beside a gallery design: sphere3.billow.json -> sphere3.result.json.
export function resultFileOf(designFile) {
  return designFile.replace(/\.billow\.json$/, '.result.json');
}
