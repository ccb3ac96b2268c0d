// The help panel: every keyboard shortcut and how to draw with a mouse, a pen or a finger. Opened with
// the Help button or "?"; text only through textContent.
export const SHORTCUTS = [
  ['V', 'View: orbit (drag; the target and inflated views turn together), zoom (wheel or pinch), pan (right drag or two fingers)'],
  ['1 / 3 / 7', 'Turn the view to see the target straight from the front, the right or above (the View menu has every side), as an Outline seam is laid'],
  ['9', 'Turn the view to the opposite side'],
  ['D', 'Draw seams: click points on the target; click the first point to close a loop'],
  ['S', 'Section seam: click the target for a seam all around it where a plane through that point cuts it; with a Band width, two seams with a gusset strip between them'],
  ['O', 'Outline seam: a seam around the shape as seen from here, for a front and a back panel (on a shape with handles, with the seams that make every part a panel)'],
  ['E', 'Edit seams: drag control points; double-click a seam to add a point'],
  ['Enter', 'Finish the seam being drawn (or the Finish button, for touch)'],
  ['Esc', 'Cancel the seam being drawn; back to View'],
  ['Backspace', 'Remove the last point of the seam being drawn'],
  ['Delete', 'Delete the selected control point (Edit)'],
  ['M', 'Mirror symmetry: off, across X, Y, Z'],
  ['C', 'Colors of the inflated shape: wrinkles, stress, distance to target'],
  ['N', 'Pattern view: the panels side by side, or nested on the sheet as cut'],
  ['Ctrl+Z', 'Undo'],
  ['Ctrl+Shift+Z / Ctrl+Y', 'Redo'],
  ['Ctrl+S', 'Save the design as a file'],
  ['Ctrl+O', 'Open a mesh, design or pattern file'],
  ['?', 'This help'],
];

// In the classroom walk (the Classroom button, or a link ending in #classroom).
export const CLASSROOM_SHORTCUTS = [
  ['→ / Page Down / Space', 'Classroom: next step'],
  ['← / Page Up', 'Classroom: previous step'],
  ['Home / End', 'Classroom: first / last step'],
  ['Esc', 'Classroom: leave the walk; your own design comes back'],
];

export class Help {
  constructor(dialog) {
    this.dialog = dialog;
    const title = document.createElement('h2');
    title.textContent = 'Keyboard shortcuts and drawing';
    const close = document.createElement('button');
    close.type = 'button';
    close.className = 'close';
    close.textContent = 'Close';
    close.title = 'Close the shortcuts (Esc)';
    close.addEventListener('click', () => dialog.close());
    const table = document.createElement('table');
    for (const [keys, what] of [...SHORTCUTS, ...CLASSROOM_SHORTCUTS]) {
      const row = table.insertRow();
      const keyCell = row.insertCell();
      keys.split(' / ').forEach((combo, i) => {
        if (i) keyCell.append(' or ');
        combo.split('+').forEach((k, j) => {
          if (j) keyCell.append('+');
          const kbd = document.createElement('kbd');
          kbd.textContent = k;
          keyCell.append(kbd);
        });
      });
      row.insertCell().textContent = what;
    }
    const touch = document.createElement('p');
    touch.textContent =
      'On a tablet: tap points to draw (a tap, not a drag); use Finish, Close loop and Cancel in the seam panel; drag a control point with a finger in Edit. Pens work like a mouse.';
    const more = document.createElement('p');
    more.textContent =
      'Compare (top bar): keep the current seams as Layout A, change them, and compare panels, distance to target and wrinkles; Use puts a kept layout back, Undo returns. Classroom (top bar): a walk through the method on an example, for teaching; Full screen for a projector, Larger text for the back of the room.';
    const pattern = document.createElement('p');
    pattern.textContent =
      'Seam allowance per seam (Pattern pane): click a seam, or open Seams and pick it, then type its allowance and press Enter (0 for a heat-sealed seam); an empty field or ↺ gives it the seam allowance again. The seams are labelled S1, S2, ... as on the cut pieces. Grain: Keep grain nests each panel with its up (as in the Pattern pane) along the roll.';
    dialog.append(close, title, table, touch, more, pattern);
  }

  open() {
    if (!this.dialog.open) this.dialog.showModal();
  }
}
