// Small page helpers: a download of a blob, a passing message in the footer,
// a link to share.

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
