// Light and dark themes, and large type for projectors. The choice ('auto' follows the system, 'light',
// 'dark') and large type are remembered in localStorage; the page's colors are CSS variables switched by
// data-theme on <html> (styles.css); onChange lets the WebGL panes take the new background.
const THEME_KEY = 'billow-theme';
const LARGE_KEY = 'billow-large-type';
export const THEMES = ['auto', 'light', 'dark'];

function stored(key, fallback) {
  try {
    return localStorage.getItem(key) ?? fallback;
  } catch {
    return fallback;
  }
}

function store(key, value) {
  try {
    localStorage.setItem(key, value);
  } catch {
    // private mode or storage refused: the choice lasts for this page only
  }
}

export class Theme {
  constructor({ onChange = () => {} } = {}) {
    this.onChange = onChange;
    this.choice = THEMES.includes(stored(THEME_KEY, 'auto')) ? stored(THEME_KEY, 'auto') : 'auto';
    this.largeType = stored(LARGE_KEY, 'false') === 'true';
    this.media = globalThis.matchMedia?.('(prefers-color-scheme: dark)');
    this.media?.addEventListener?.('change', () => this.choice === 'auto' && this.apply());
    this.apply();
  }

  // 'light' or 'dark': what the page shows now.
  get resolved() {
    if (this.choice !== 'auto') return this.choice;
    return this.media?.matches ? 'dark' : 'light';
  }

  set(choice) {
    if (!THEMES.includes(choice)) return;
    this.choice = choice;
    store(THEME_KEY, choice);
    this.apply();
  }

  setLargeType(on) {
    this.largeType = Boolean(on);
    store(LARGE_KEY, String(this.largeType));
    this.apply();
  }

  apply() {
    const root = document.documentElement;
    root.dataset.theme = this.resolved;
    root.dataset.largeType = String(this.largeType);
    this.onChange(this);
  }

  // A CSS variable of the current theme (e.g. '--pane-bg').
  color(name) {
    return getComputedStyle(document.documentElement).getPropertyValue(name).trim();
  }
}
