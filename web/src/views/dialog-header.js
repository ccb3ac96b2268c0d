// The header of the app's own dialogs (gallery, layout comparison): a titled h2 the dialog is labelled by,
// and a Close button. Text only through textContent.
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
