// Small page helpers: a download of a blob, a passing message in the footer,
// a link to share, a banner and a tooltip.

/** Downloads `blob` as file `name`. */
export function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 5000);
}

/** Shows `text` in the footer's #toast for 2.5 s. */
export function toast(text) {
  const el = document.getElementById('toast');
  if (!el) return;
  el.textContent = text;
  setTimeout(() => {
    if (el.textContent === text) el.textContent = '';
  }, 2500);
}

/** Puts the link with `fragment` in the address bar and on the clipboard, and says which. */
export async function shareLink(fragment, t) {
  const url = `${location.origin}${location.pathname}${fragment}`;
  history.replaceState(null, '', url);
  try {
    await navigator.clipboard.writeText(url);
    toast(t('shared'));
  } catch {
    toast(t('share_failed'));
  }
}

/** Shows `text` in banner `el`, or hides it (no text). */
export function showBanner(el, text) {
  el.hidden = !text;
  el.textContent = text || '';
}

/** Shows tooltip `el` with `text` near the pointer at (`x`, `y`), kept inside the window; hides it when `text` is null. */
export function showTip(el, text, x, y) {
  if (text === null) {
    el.hidden = true;
    return;
  }
  el.textContent = text;
  el.hidden = false;
  el.style.left = `${Math.min(x + 14, window.innerWidth - el.offsetWidth - 8)}px`;
  el.style.top = `${y + 16}px`;
}
