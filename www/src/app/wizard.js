// The thread wizard: a designation (or a major diameter and a lead), the
// thread's length or end, external or internal, starts, the tool and the
// machine's limits, a controller and a form → a program written by the
// planner (src/wizard.rs, through the engine's `tool` message). The program
// is shown as it is written, with the wizard's notes; "Open as a new
// program" hands it to the caller, which keeps the user's own program.

import { esc } from '../shared/table.js';

/** The fields of the form: [name, i18n key, input attributes, default]. */
const FIELDS = [
  ['designation', 'wz_designation', 'type="text" maxlength="200" spellcheck="false" autocomplete="off" placeholder="M30x2-6g"', 'M30x2-6g'],
  ['major', 'wz_major', 'type="number" step="any" min="0.1" max="10000"', ''],
  ['lead', 'wz_lead', 'type="number" step="any" min="0.01" max="1000"', ''],
  ['length', 'wz_length', 'type="number" step="any" min="0.01" max="100000"', '30'],
  ['startZ', 'wz_start_z', 'type="number" step="any"', '0'],
  ['endZ', 'wz_end_z', 'type="number" step="any"', ''],
  ['starts', 'wz_starts', 'type="number" step="1" min="1" max="360"', ''],
  ['noseRadius', 'wz_nose', 'type="number" step="any" min="0" max="10"', '0'],
  ['maxRpm', 'wz_max_rpm', 'type="number" step="any" min="1" max="100000"', '1000'],
  ['maxFeed', 'wz_max_feed', 'type="number" step="any" min="1" max="1000000"', '3000'],
];

/** The written program and its notes (after `before`), and the Open and Cancel buttons: what both dialogs end with. */
const outputHtml = (t, before) => `<div class="wz-out">
      ${before}
      <pre class="wz-program" tabindex="0" aria-label="${esc(t('wz_program'))}"></pre>
      <ul class="wz-notes"></ul>
    </div>
    <div class="wz-buttons"><button type="button" value="open" class="primary" disabled>${esc(t('wz_open'))}</button><button type="submit" value="cancel">${esc(t('wz_cancel'))}</button></div>`;

/** Shows `out` (`{program, notes}`) in dialog `dlg`, or `text` when there is none (Open then disabled). */
function showOutput(dlg, out, text) {
  dlg.querySelector('.wz-program').textContent = out ? out.program : text;
  dlg.querySelector('.wz-notes').innerHTML = out ? out.notes.map((n) => `<li>${esc(n)}</li>`).join('') : '';
  dlg.querySelector('[value="open"]').disabled = !out;
}

/**
 * Opens the wizard. `request(what, payload)` asks the engine (`tool`
 * messages); `onOpen({name, text, dialect})` receives the program.
 * `dialect` is preselected. Returns the dialog element (removed on close).
 */
export async function openWizard({ request, t, dialect, onOpen }) {
  const targets = await request({ what: 'forms' });
  const dlg = document.createElement('dialog');
  dlg.className = 'wizard';
  dlg.setAttribute('aria-labelledby', 'wz-title');
  const field = ([name, key, attrs, value]) => `<label class="wz-field"><span>${esc(t(key))}</span><input name="${name}" ${attrs} value="${esc(value)}"></label>`;
  dlg.innerHTML = `<form method="dialog" class="wz-form">
    <h2 id="wz-title">${esc(t('wz_title'))}</h2>
    <p class="wz-help">${esc(t('wz_help'))}</p>
    <div class="wz-grid">
      ${FIELDS.map(field).join('')}
      <label class="wz-field"><span>${esc(t('wz_kind'))}</span><select name="kind">
        <option value="">${esc(t('wz_kind_auto'))}</option><option value="external">${esc(t('wz_external'))}</option><option value="internal">${esc(t('wz_internal'))}</option></select></label>
      <label class="wz-field"><span>${esc(t('dialect'))}</span><select name="dialect">${targets
        .map((d) => `<option value="${esc(d.dialect)}"${d.dialect === dialect ? ' selected' : ''}>${esc(d.title)}</option>`)
        .join('')}</select></label>
      <label class="wz-field"><span>${esc(t('wz_form'))}</span><select name="form"></select></label>
    </div>
    ${outputHtml(t, '<p class="wz-error" role="alert" hidden></p>')}
  </form>`;
  document.body.append(dlg);
  const form = dlg.querySelector('form');
  const $ = (sel) => dlg.querySelector(sel);
  const fillForms = () => {
    const d = targets.find((x) => x.dialect === form.dialect.value) || targets[0];
    const keep = form.form.value;
    form.form.innerHTML = d.forms.map((f) => `<option value="${esc(f.name)}">${esc(f.title)}</option>`).join('');
    if (d.forms.some((f) => f.name === keep)) form.form.value = keep;
  };
  fillForms();
  let last = null;
  let seq = 0;
  const update = async () => {
    const mine = ++seq;
    const req = { dialect: form.dialect.value, form: form.form.value };
    for (const [name] of FIELDS) req[name] = form[name].value;
    if (form.kind.value) req.internal = form.kind.value === 'internal';
    // An end Z replaces the length.
    if (req.endZ !== '') req.length = '';
    let out = null;
    let error = null;
    try {
      out = await request({ what: 'generate', request: req });
    } catch (e) {
      error = e.message;
    }
    if (mine !== seq) return;
    last = out ? { ...out, dialect: req.dialect } : null;
    $('.wz-error').hidden = !error;
    $('.wz-error').textContent = error || '';
    showOutput(dlg, out, '');
  };
  let timer = 0;
  form.addEventListener('input', (e) => {
    if (e.target === form.dialect) fillForms();
    clearTimeout(timer);
    timer = setTimeout(update, 150);
  });
  form.addEventListener('change', (e) => {
    if (e.target === form.dialect) fillForms();
    clearTimeout(timer);
    timer = setTimeout(update, 0);
  });
  $('[value="open"]').addEventListener('click', () => {
    if (!last) return;
    const title = last.spec && last.spec.title ? last.spec.title : t('wz_title');
    onOpen({ name: `${title} · ${form.form.selectedOptions[0]?.textContent || ''}`.trim(), text: last.program, dialect: last.dialect });
    dlg.close();
  });
  dlg.addEventListener('close', () => dlg.remove());
  dlg.showModal();
  await update();
  return dlg;
}

/**
 * Opens "Expand to blocks": the last plan written block by block for a
 * controller chosen from `dialects` (`[{name, title}]`, `dialect`
 * preselected), previewed with its notes; "Open as a new program" hands it
 * to `onOpen({text, dialect})`. `alarms`: the plan's alarm count (the
 * expansion writes what was planned, so it says so).
 */
export async function openExpand({ request, t, dialects, dialect, alarms, onOpen }) {
  const dlg = document.createElement('dialog');
  dlg.className = 'wizard';
  dlg.setAttribute('aria-labelledby', 'ex-title');
  dlg.innerHTML = `<form method="dialog" class="wz-form">
    <h2 id="ex-title">${esc(t('ex_title'))}</h2>
    <p class="wz-help">${esc(t('ex_help'))}</p>
    <div class="wz-grid">
      <label class="wz-field"><span>${esc(t('ex_to'))}</span><select name="to">${dialects
        .map((d) => `<option value="${esc(d.name)}"${d.name === dialect ? ' selected' : ''}>${esc(d.title)}</option>`)
        .join('')}</select></label>
      <p class="wz-error" role="alert"${alarms ? '' : ' hidden'}>${esc(t('ex_alarms', { n: alarms }))}</p>
    </div>
    ${outputHtml(t, '')}
  </form>`;
  document.body.append(dlg);
  const form = dlg.querySelector('form');
  let last = null;
  const update = async () => {
    const to = form.to.value;
    let out = null;
    let error = null;
    try {
      out = await request({ what: 'expand', to });
    } catch (e) {
      error = e.message;
    }
    if (to !== form.to.value) return;
    last = out ? { text: out.program, dialect: to } : null;
    showOutput(dlg, out, error);
  };
  form.to.addEventListener('change', update);
  dlg.querySelector('[value="open"]').addEventListener('click', () => {
    if (!last) return;
    onOpen(last);
    dlg.close();
  });
  dlg.addEventListener('close', () => dlg.remove());
  dlg.showModal();
  await update();
  return dlg;
}
