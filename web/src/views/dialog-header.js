// The app's own dialogs (gallery, layout comparison, suggested seams): the header, a titled h2 the dialog is
// labelled by, and a Close button; the side panels' frame and place. Text only through textContent.
export function dialogHeader(dialog, { id, title, closeClass, closeTitle = '', onClose }) {
  dialog.setAttribute('aria-labelledby', id);
  const header = document.createElement('header');
  const heading = document.createElement('h2');
  heading.id = id;
  heading.textContent = title;
  const close = document.createElement('button');
  close.type = 'button';
  close.className = closeClass;
  close.textContent = 'Close';
  if (closeTitle) close.title = closeTitle;
  close.addEventListener('click', onClose);
  header.append(heading, close);
  return header;
}

// A side panel (the layout comparison, suggested seams): a dialog of class `name`-dialog with its header and a body
// of class `name`-body, in the page. The header stays put and the body scrolls (a sticky header made Chromium leave
// a strip of the canvas below unpainted, in the pattern pane). Returns { dialog, body }.
export function sidePanel(name, { title, closeTitle, onClose }) {
  const dialog = document.createElement('dialog');
  dialog.className = `${name}-dialog`;
  const header = dialogHeader(dialog, { id: `${name}-title`, title, closeClass: `${name}-close`, closeTitle, onClose });
  const body = document.createElement('div');
  body.className = `${name}-body`;
  dialog.append(header, body);
  document.body.append(dialog);
  return { dialog, body };
}

// Shows a side panel over the inflated pane, not modal, so the target and its seams stay in view and editable
// beside it; its bottom stays in the inflated pane, off the pattern pane's figures below (its body scrolls), or with
// `down`, reaches the window's foot (suggested layouts: their pictures need the room, and no panels are made while
// they are tried).
export function showOverInflatedPane(dialog, { down = false } = {}) {
  const pane = document.getElementById('pane-inflated')?.getBoundingClientRect();
  if (pane) {
    const top = Math.round(pane.top + 34);
    const bottom = down ? window.innerHeight - 8 : pane.bottom - 6;
    dialog.style.top = `${top}px`;
    dialog.style.maxHeight = `max(12rem, ${Math.round(bottom - top)}px)`;
  }
  if (!dialog.open) dialog.show();
}
