// The boxes docked over the panes (web/index.html: a .box with a .box-toggle title over its .box-content)
// close to their titles and open again from them. Each starts as the page has it (closed with the class
// "collapsed": figures looked at now and then) until the designer opens or closes it; that choice is
// remembered on this device. A closed box leaves its column to the view (free-area.js).
const KEY = 'billow.boxes';

// { [box name]: true when open, false when closed } as chosen on this device.
function remembered() {
  try {
    const chosen = JSON.parse(localStorage.getItem(KEY) ?? '{}');
    return chosen && typeof chosen === 'object' && !Array.isArray(chosen) ? chosen : {};
  } catch {
    return {}; // private browsing or a damaged entry: the page's own
  }
}

export function dockBoxes(root = document) {
  const chosen = remembered();
  for (const box of root.querySelectorAll('.box[data-box]')) {
    const toggle = box.querySelector(':scope > .box-toggle');
    if (!toggle) continue;
    const name = box.dataset.box;
    const show = (open) => {
      box.classList.toggle('collapsed', !open);
      toggle.setAttribute('aria-expanded', String(open));
    };
    show(typeof chosen[name] === 'boolean' ? chosen[name] : !box.classList.contains('collapsed'));
    toggle.addEventListener('click', () => {
      const open = box.classList.contains('collapsed');
      show(open);
      chosen[name] = open;
      try {
        localStorage.setItem(KEY, JSON.stringify(chosen));
      } catch {
        // As above: the choice lasts this visit only.
      }
    });
  }
}
