// Messages to the designer: errors, warnings and notices, as text (never HTML), dismissable.
export class Messages {
  constructor(container) {
    this.container = container;
  }

  // severity: 'error' | 'warning' | 'notice'; items: optional list of detail lines.
  // The same message twice in a row is shown once (the newer replaces the older, so it comes last).
  show(severity, text, items = []) {
    const key = `${severity}\n${text}\n${items.join('\n')}`;
    for (const old of this.container.children) if (old.dataset.key === key) old.remove();
    const box = document.createElement('div');
    box.className = `message ${severity}`;
    box.setAttribute('role', severity === 'error' ? 'alert' : 'status');
    box.dataset.severity = severity;
    box.dataset.key = key;
    const body = document.createElement('div');
    body.className = 'text';
    body.textContent = text;
    if (items.length) {
      const list = document.createElement('ul');
      for (const item of items) {
        const li = document.createElement('li');
        li.textContent = item;
        list.append(li);
      }
      body.append(list);
    }
    const close = document.createElement('button');
    close.type = 'button';
    close.title = 'Dismiss';
    close.setAttribute('aria-label', 'Dismiss message');
    close.textContent = '×';
    close.addEventListener('click', () => box.remove());
    box.append(body, close);
    this.container.append(box);
    return box;
  }

  clear() {
    this.container.replaceChildren();
  }
}
