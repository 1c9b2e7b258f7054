// The buttons above each drawing: Fit, Stretch radially, Roughing (the
// G71/G72 cuts, drawn on demand), SVG and PNG.
// Exports are the engine's (the core's display list written as SVG, or the
// canvas painting it); a view with nothing to export says why.

import { t } from '../shared/i18n.js';
import { download, toast } from './pageutil.js';

/** Binds the bar of panel `panel` (an element) to view `name` of the engine `client`; other buttons' acts go to `other(act)`. */
export function bindViewBar(panel, name, client, other = () => {}) {
  panel.querySelector('.bar').addEventListener('click', async (e) => {
    const act = e.target.dataset?.act;
    if (act && !['fit', 'stretch', 'roughing', 'svg', 'png'].includes(act)) other(act);
    if (act === 'fit') client.send({ type: 'input', name, op: 'fit' });
    if (act === 'stretch' || act === 'roughing') e.target.setAttribute('aria-pressed', String(await client.request('input', { name, op: act })));
    if (act === 'svg' || act === 'png') {
      try {
        const data = await client.request('export', { name, format: act, scale: 2 });
        if (data) download(`screwcut-${name}.${act}`, act === 'svg' ? new Blob([data], { type: 'image/svg+xml' }) : data);
        else toast(t('export_empty', { view: t(name) }));
      } catch (err) {
        const why = /no thread/.test(String(err?.message)) ? t('export_no_thread') : String(err?.message || err);
        toast(t('export_failed', { view: t(name), why }));
      }
    }
  });
}
