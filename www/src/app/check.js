// The thread check above the pass table: the designation the thread is
// judged by (a comment before the thread, or the setting
// `thread.designation` typed here), the verdict with the pitch diameter
// against its limits and the change of the final pass's X that centres it,
// and the shop-floor figures: cycle time, spindle speed, thread feed, helix
// angle, lead-in δ1 and run-out δ2 against what the speed needs. Everything
// shown is computed by the planner (src/shop, `thread.shop`); this module
// only lays it out.

import { getLang } from '../shared/i18n.js';
import { esc, num } from '../shared/table.js';

/** The setting the designation field edits. */
export const DESIGNATION = 'thread.designation';

const u = (units) => (units === 'inch' ? 'in' : 'mm');
const fixed = (v, d) => (v == null || v === undefined ? '' : Number(v).toFixed(d));

/** The verdict line of thread summary `th`, as HTML (details in the titles). */
export function verdictHtml(th, units, t) {
  if (!th) return '';
  const g = th.shop ? th.shop.gauge : null;
  if (!g) return `<span class="none">${esc(t('check_none'))}</span>`;
  const from = g.source === 'comment' ? t('check_from_comment', { line: g.line }) : t('check_from_setting');
  // The summary carries the notes in each language (`th.notes.en`, `th.notes.zh`); the plan's JSON keeps them in English.
  const notes = [from, ...((th.notes && th.notes[getLang()]) || g.notes || [])].join('\n');
  const head = `<span class="verdict ${g.ok ? 'ok' : 'fail'}" title="${esc(notes)}">${g.ok ? '✓' : '✗'} ${esc(g.designation)} ${esc(g.ok ? t('check_ok') : t('check_fail'))}</span>`;
  const parts = [`${esc(t('check_d2'))} ${esc(num(g.pitch_diameter))}`];
  if (g.pitch_diameter_min != null && g.pitch_diameter_max != null) {
    parts.push(esc(t('check_limits', { min: num(g.pitch_diameter_min), max: num(g.pitch_diameter_max), u: u(units) })));
  }
  if (g.delta_x != null && Math.abs(g.delta_x) >= 0.0005) {
    const dx = t('check_dx', { dx: (g.delta_x > 0 ? '+' : '−') + num(Math.abs(g.delta_x)) });
    parts.push(`<span class="dx" title="${esc(t('check_dx_help'))}">${esc(dx)}</span>`);
  }
  if (g.over_wires) {
    const o = g.over_wires;
    const text = t('check_wires', { m: num(o.m), w: num(o.wire), min: o.m_min == null ? '?' : num(o.m_min), max: o.m_max == null ? '?' : num(o.m_max) });
    parts.push(`<span class="wires" title="${esc(t('check_wires_help'))}">${esc(text)}</span>`);
  }
  if (g.nose_radius_assumed) {
    const r = g.gauges_with_nose;
    const help = r ? t('check_nose_range', { lo: num(r[0]), hi: num(r[1]) }) : t('check_nose_none');
    parts.push(`<span class="nose" title="${esc(help)}">${esc(t('check_nose', { r: num(g.nose_radius) }))}</span>`);
  }
  return `${head} ${parts.join(' · ')}`;
}

/** The shop-floor figures of thread summary `th`, as HTML (each part escaped) (a warning class where a figure is short of what the speed needs). */
export function figuresHtml(th, units, t) {
  const s = th && th.shop;
  if (!s) return '';
  const parts = [];
  if (s.time_s != null) parts.push(esc(t('check_time', { s: fixed(s.time_s, 1), cut: fixed(s.cut_time_s, 1) })));
  else parts.push(esc(t('check_no_speed')));
  if (s.rpm != null) parts.push(esc(t('check_rpm', { n: fixed(s.rpm, 0) })));
  if (s.thread_feed != null) {
    const over = s.rpm_limit != null && s.rpm != null && s.rpm > s.rpm_limit + 1e-9;
    const feed = t('check_feed', { f: fixed(s.thread_feed, 0), u: `${u(units)}/min` });
    parts.push(over ? `<b class="warn">${esc(feed)} · ${esc(t('check_rpm_limit', { n: fixed(s.rpm_limit, 0) }))}</b>` : esc(feed));
  }
  if (s.helix_angle_deg != null) parts.push(esc(t('check_helix', { a: fixed(s.helix_angle_deg, 2) })));
  const clearance = (key, have, need) => {
    if (have == null || need == null) return;
    const text = t(key, { have: num(have), need: num(need) });
    parts.push(have + 1e-9 < need ? `<b class="warn">${esc(text)}</b>` : esc(text));
  };
  clearance('check_delta1', s.lead_in, s.lead_in_needed);
  clearance('check_delta2', s.run_out, s.run_out_needed);
  if (s.clearance_source === 'assumed' && s.lead_in != null) {
    parts.push(`<span class="from" title="${esc(t('check_assumed'))}">${esc(t('check_assumed_short'))}</span>`);
  }
  return parts.join(' · ');
}

/**
 * Fills the check strip: `verdict` and `figures` elements, and the
 * designation `input` (its value follows the setting unless it has the focus).
 */
export function renderCheck({ input, verdict, figures }, th, units, t, designation, error) {
  if (document.activeElement !== input && input.value !== (designation || '')) input.value = designation || '';
  input.setAttribute('aria-invalid', error ? 'true' : 'false');
  input.title = error || t('designation_help');
  const v = error ? `<span class="verdict fail">${esc(error)}</span>` : verdictHtml(th, units, t);
  if (verdict.dataset.html !== v) {
    verdict.innerHTML = v;
    verdict.dataset.html = v;
  }
  const f = figuresHtml(th, units, t);
  if (figures.dataset.html !== f) {
    figures.innerHTML = f;
    figures.dataset.html = f;
  }
}

/** Calls `change(value)` (trimmed) a quarter second after the designation field stops changing. */
export function bindDesignation(input, change) {
  let timer = 0;
  input.addEventListener('input', () => {
    clearTimeout(timer);
    timer = setTimeout(() => change(input.value.trim()), 250);
  });
}
