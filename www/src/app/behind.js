// The drawing behind the text. While a plan takes longer than a moment
// (planning.js decides when), the drawings and the pass table fade as the
// display list's stale style fades them, the side section says that it
// shows an earlier text and for how long the latest has been planning, and
// the footer's summary says it is the earlier text's, until the new plan
// arrives. The engine may be busy for seconds (the drawings are its work),
// so the page does this itself, with CSS over the canvases.

import { t } from '../shared/i18n.js';

let ticking = null;

/** The drawing is behind the text since `since` (performance.now()), or caught up (`null`). */
export function showBehind(since) {
  const banner = document.getElementById('behind');
  const summary = document.getElementById('summary');
  clearInterval(ticking);
  ticking = null;
  if (since === null) {
    delete document.body.dataset.behind;
    banner.hidden = true;
    summary.removeAttribute('data-behind');
    return;
  }
  const render = () => {
    banner.textContent = t('behind', { s: ((performance.now() - since) / 1000).toFixed(1) });
    summary.dataset.behind = t('behind_short');
  };
  document.body.dataset.behind = 'true';
  banner.hidden = false;
  render();
  ticking = setInterval(render, 250);
}
