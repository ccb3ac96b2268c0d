// Messages to the designer: errors, warnings and notices, as text (never HTML), dismissable.
export class Messages {
  constructor(container) {
    this.container = container;
  }

  // severity: 'error' | 'warning' | 'notice'; items: optional list of detail lines.
  // The same message twice in a row is shown once (the newer replaces the older, so it comes last).
  // cause: what the message is about ('cut-lines', 'target.mesh.genus', ...): a newer message of the same cause
  // replaces it, and resolve(cause) takes it away once the cause is gone. locate: shows where the problem is
  // (a "Show where" button). action: { label, run }, what the message offers to do (a button; the message goes
  // when it is done).
  show(severity, text, items = [], { cause = null, locate = null, action = null } = {}) {
    const key = `${severity}\n${text}\n${items.join('\n')}`;
    for (const old of [...this.container.children]) if (old.dataset.key === key || (cause && old.dataset.cause === cause)) old.remove();
    const box = document.createElement('div');
    box.className = `message ${severity}`;
    box.setAttribute('role', severity === 'error' ? 'alert' : 'status');
    box.dataset.severity = severity;
    box.dataset.key = key;
    if (cause) box.dataset.cause = cause;
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
    if (locate) {
      const show = document.createElement('button');
      show.type = 'button';
      show.className = 'locate';
      show.textContent = 'Show where';
      show.addEventListener('click', locate);
      body.append(show);
    }
    if (action) {
      const act = document.createElement('button');
      act.type = 'button';
      act.className = 'action';
      act.textContent = action.label;
      act.addEventListener('click', () => {
        box.remove();
        action.run();
      });
      body.append(act);
    }
    box.append(body, close);
    this.container.append(box);
    return box;
  }

  // Takes away the messages of a cause that is gone: `cause` itself, and with prefix every cause starting with it.
  resolve(cause, { prefix = false } = {}) {
    for (const box of [...this.container.children]) {
      const c = box.dataset.cause;
      if (c && (c === cause || (prefix && c.startsWith(cause)))) box.remove();
    }
  }

  clear() {
    this.container.replaceChildren();
  }
}
