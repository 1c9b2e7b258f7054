// The pass table and the small formatting helpers shared by the app and
// the embedded preview.

/** A number as the tables show it: at most four decimals, '' for none. */
export const num = (v) => (v === undefined || v === null ? '' : String(Math.round(v * 1e4) / 1e4));

/** Text escaped for HTML content and attribute values. */
export const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

/** The header row of the pass table, with `t(key)` giving the column titles. */
export function passTableHead(t) {
  return `<tr><th>${t('col_pass')}</th><th>${t('col_start')}</th><th>${t('col_x')}</th><th>${t('col_z')}</th><th>${t('col_z_end')}</th><th>${t('col_depth')}</th><th>${t('col_infeed')}</th><th>${t('col_area')}</th><th class="role">${t('col_role')}</th><th class="role">${t('col_lines')}</th></tr>`;
}

/** The body rows of the pass table for the chosen thread's `passes`, one HTML string per row. */
export function passTableRowList(passes, t) {
  return (passes || []).map(
    (p, i) =>
      `<tr data-pass="${i}" class="${p.role}"><td>${p.index}</td><td>${p.start}</td><td>${num(p.from[0])}</td><td>${num(p.from[1])}</td><td>${num(p.to[1])}</td><td>${num(p.depth)}</td><td>${num(p.infeed)}</td><td>${num(p.area)}</td><td class="role">${t(p.role)}</td><td class="lines">${p.lines.join(',')}</td></tr>`,
  );
}

/** The body rows of the pass table for the chosen thread's `passes`. */
export function passTableRows(passes, t) {
  return passTableRowList(passes, t).join('');
}
