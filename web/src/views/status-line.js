// The top bar's status keeps to one line, cut short with an ellipsis (styles.css), so a long status never
// adds a row to the bar and moves the panes; its full text is its tooltip.
export function statusTooltip(element) {
  const update = () => {
    element.title = element.textContent;
  };
  // Attributes are not observed: setting the title does not call this again.
  new MutationObserver(update).observe(element, { childList: true, characterData: true, subtree: true });
  update();
}
