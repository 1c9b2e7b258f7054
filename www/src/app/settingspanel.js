// The Parameters panel: one row per setting of the controller (its name,
// an input of its kind, unit, help in the page's language, default and
// range), the rows changed from the default marked, and the planner's
// setting errors shown on their rows.

import { choiceText, unitText } from '../shared/i18n.js';
import { esc, num } from '../shared/table.js';

export class SettingsPanel {
  /**
   * @param {HTMLElement} form the panel's form
   * @param {{table: (dialect: string) => Promise<object[]>, t: Function, lang: () => string}} opts
   *   `table` answers the controller's settings table (src/wasm/bind.rs `settings_table`)
   */
  constructor(form, opts) {
    this.form = form;
    this.opts = opts;
    this.table = [];
  }

  /** Builds the rows of `dialect`'s settings with the user's `values` ({name: value}). */
  async build(dialect, values) {
    const { t } = this.opts;
    this.table = await this.opts.table(dialect);
    const zh = this.opts.lang() === 'zh';
    this.form.innerHTML = this.table
      // The designation has its own field above the pass table.
      .filter((s) => s.name !== 'thread.designation')
      .map((s) => {
        const id = `set-${s.name.replace(/[^a-z0-9]/gi, '_')}`;
        const v = values[s.name];
        let input;
        if (s.kind === 'choice') {
          input = `<select id="${id}" data-name="${esc(s.name)}">${s.choices
            .map((c, i) => `<option value="${esc(c)}"${(v ?? s.choices[s.default]) === c ? ' selected' : ''}>${esc(choiceText(c))}${i === s.default ? ' *' : ''}</option>`)
            .join('')}</select>`;
        } else if (s.kind === 'text') {
          input = `<input type="text" id="${id}" data-name="${esc(s.name)}" maxlength="${s.max}" spellcheck="false" autocomplete="off" value="${esc(v ?? '')}">`;
        } else if (s.kind === 'bool') {
          const on = v === undefined ? s.default !== 0 : v === '1';
          input = `<input type="checkbox" id="${id}" data-name="${esc(s.name)}"${on ? ' checked' : ''}>`;
        } else {
          const step = s.kind === 'int' ? '1' : 'any';
          input = `<input type="number" id="${id}" data-name="${esc(s.name)}" step="${step}" min="${s.min}" max="${s.max}" value="${esc(v ?? s.default)}">`;
        }
        const range = s.kind === 'text' ? t('text_setting', { n: s.max }) : `${t('default')} ${num(s.default)} · ${t('range')} ${num(s.min)}…${num(s.max)}`;
        return `<div class="setting${v !== undefined ? ' changed' : ''}" data-name="${esc(s.name)}"><label for="${id}">${esc(s.name)} ${input} <span class="unit">${esc(unitText(s.unit))}</span></label><div class="help" title="${esc(range)}">${esc(zh ? s.help_zh : s.help)} <span class="unit">(${esc(range)})</span></div><div class="err"></div></div>`;
      })
      .join('');
  }

  /**
   * Applies a change of input `el` to `mine` (the user's values of the
   * controller): a value equal to the default, or empty, is removed.
   * Returns whether `el` is a setting's input.
   */
  change(el, mine) {
    const name = el.dataset.name;
    if (!name) return false;
    const def = this.table.find((s) => s.name === name);
    const value = el.type === 'checkbox' ? (el.checked ? '1' : '0') : el.value.trim();
    const isDefault = def && def.kind !== 'text' && ((def.kind === 'choice' && def.choices[def.default] === value) || (def.kind !== 'choice' && value !== '' && Number(value) === def.default));
    if (isDefault || value === '') delete mine[name];
    else mine[name] = value;
    el.closest('.setting').classList.toggle('changed', !isDefault && value !== '');
    return true;
  }

  /** Shows the planner's setting errors (`[{setting, message}]`) on their rows. */
  showErrors(list) {
    for (const el of this.form.querySelectorAll('.setting .err')) el.textContent = '';
    for (const e of list || []) {
      const row = [...this.form.querySelectorAll('.setting')].find((d) => d.dataset.name.toLowerCase() === e.setting.toLowerCase());
      if (row) row.querySelector('.err').textContent = e.message;
    }
  }
}
