// "Compare with…": another program of the list planned beside this one,
// its passes laid over the side and tooth sections in their own pen (the
// core draws them: src/diagram/overlay.rs), and what differs pass by pass
// (src/compare.rs) in a strip above the side section. Each later plan of
// this program is compared again; "Stop" takes the other program off.

import { esc, num } from '../shared/table.js';

/** The settings of entry `e` in its dialect as `NAME=VALUE` lines. */
const settingsOf = (e) =>
  Object.entries((e.settings && e.settings[e.dialect]) || {})
    .map(([k, v]) => `${k}=${v}`)
    .join('\n');

export class Compare {
  /**
   * @param {{client, library, t: Function, currentId: Function, onShown: Function}} o
   *   `currentId()`: the open program's entry id; `strip`: the element the differences go in.
   */
  constructor({ client, library, t, currentId, strip }) {
    Object.assign(this, { client, library, t, currentId, strip });
    this.name = null; // the other program's name while comparing
    strip.addEventListener('click', (e) => {
      if (e.target.closest('[data-act="compare-stop"]')) this.stop();
    });
  }

  /** Opens the dialog that chooses the other program from the list. */
  open() {
    const t = this.t;
    const others = this.library.programs.list().filter((i) => i.id !== this.currentId());
    const dlg = document.createElement('dialog');
    dlg.className = 'wizard';
    dlg.setAttribute('aria-labelledby', 'cmp-title');
    dlg.innerHTML = `<form method="dialog" class="wz-form">
      <h2 id="cmp-title">${esc(t('cmp_title'))}</h2>
      <p class="wz-help">${esc(t('cmp_help'))}</p>
      ${
        others.length
          ? `<label class="wz-field"><span>${esc(t('cmp_with'))}</span><select name="other">${others.map((i) => `<option value="${esc(i.id)}">${esc(i.name || i.id)}</option>`).join('')}</select></label>`
          : `<p class="wz-error" role="alert">${esc(t('cmp_none'))}</p>`
      }
      <div class="wz-buttons"><button value="cancel">${esc(t('close'))}</button><button value="compare"${others.length ? '' : ' disabled'}>${esc(t('cmp_go'))}</button></div>
    </form>`;
    document.body.append(dlg);
    dlg.querySelector('[value="compare"]').addEventListener('click', (e) => {
      e.preventDefault();
      const id = dlg.querySelector('select')?.value;
      dlg.close();
      if (id) this.start(id);
    });
    dlg.addEventListener('close', () => dlg.remove());
    dlg.showModal();
    return dlg;
  }

  /** Compares with entry `id` of the list. */
  async start(id) {
    const e = this.library.programs.get(id);
    if (!e) return;
    this.name = e.name || id;
    const comparison = await this.client.request('compare', { text: e.program, dialect: e.dialect, settings: settingsOf(e) });
    this.show(comparison);
  }

  /** Takes the other program off the drawings. */
  async stop() {
    this.name = null;
    this.strip.hidden = true;
    this.strip.innerHTML = '';
    await this.client.request('compare_off');
  }

  /** Shows a comparison (`{same, threads, passes, differences}`) in the strip. */
  show(c) {
    if (!this.name || !c) return;
    const t = this.t;
    const d = c.differences || [];
    const head = c.same ? t('cmp_same', { name: this.name, passes: c.passes[0] }) : t('cmp_differ', { name: this.name, n: d.length, a: c.passes[0], b: c.passes[1] });
    const where = (x) => (x.pass ? t('cmp_at_pass', { thread: x.thread, pass: x.pass, start: x.start }) : x.thread ? t('cmp_at_thread', { thread: x.thread }) : t('cmp_at_program'));
    const rows = d
      .slice(0, 200)
      .map((x) => `<tr><td>${esc(where(x))}</td><td>${esc(t(`cmp_${x.what}`))}</td><td>${x.a === null ? '—' : num(x.a)}</td><td>${x.b === null ? '—' : num(x.b)}</td></tr>`)
      .join('');
    this.strip.innerHTML = `<span class="cmp-key" aria-hidden="true"></span><span class="cmp-head">${esc(head)}</span>${
      d.length
        ? `<details><summary>${esc(t('cmp_details'))}</summary><table><thead><tr><th>${esc(t('cmp_where'))}</th><th>${esc(t('cmp_what'))}</th><th>${esc(t('cmp_this'))}</th><th>${esc(this.name)}</th></tr></thead><tbody>${rows}</tbody></table></details>`
        : ''
    }<button data-act="compare-stop">${esc(t('cmp_stop'))}</button>`;
    this.strip.classList.toggle('same', !!c.same);
    this.strip.hidden = false;
  }
}
