// The page's menus and their dialogs: the examples, the File menu (open,
// save, print, the plan as JSON), sharing a link, the wizard and `expand`
// (a bundle of their own, fetched when one first opens), and the settings
// panel's buttons. What they act on comes from the app (main.js) as a
// context: nothing here keeps state of its own but the examples' list.

import { getLang, t } from '../shared/i18n.js';
import { esc } from '../shared/table.js';
import { fileName, fillPrintSheet, openFile } from './files.js';
import { download, shareLink, toast } from './pageutil.js';
import { inherited } from './programs.js';
import { encodeFragment } from './share.js';

const $ = (id) => document.getElementById(id);

/** The examples' list (examples/index.json), read once by `loadExamples`. */
let examples = [];

/** Reads the examples' list and fills the menu; `[]` (and an entry in `errors`) when it cannot be read. */
export async function loadExamples(errors) {
  try {
    const res = await fetch('examples/index.json');
    examples = await res.json();
    $('examples').dataset.list = JSON.stringify(examples);
    renderExamples();
    return examples;
  } catch (e) {
    errors.push(`examples: ${e}`);
    return [];
  }
}

/** Fills the examples' menu in the page's language. */
export function renderExamples() {
  const zh = getLang() === 'zh';
  $('examples').innerHTML = `<option value="">${esc(t('example_pick'))}</option>` + examples.map((e, i) => `<option value="${i}">${esc(zh && e.title_zh ? e.title_zh : e.title)}</option>`).join('');
}

/** Opens example `entry` as a program of its own in `ctx.library` (the open one stays in the Programs menu). */
export async function openExample(ctx, entry) {
  const res = await fetch(`examples/${encodeURIComponent(entry.file)}`);
  const text = await res.text();
  await ctx.library.openNew({ dialect: entry.dialect || ctx.state.dialect, settings: inherited(ctx.state.settings), program: text });
}

/**
 * Binds the menus. `ctx`: `state` (dialect, settings), `client`, `library`,
 * `dialects`, `editor()`, `result()` (the last answer), `persist()`,
 * `replan()`, `buildSettings()`.
 */
export function bindMenus(ctx) {
  const { state, client, library } = ctx;
  const openText = ({ text, dialect }) => library.openNew({ dialect, settings: inherited(state.settings), program: text });
  $('examples').addEventListener('change', async (e) => {
    const entry = examples[Number(e.target.value)];
    e.target.value = '';
    if (entry) await openExample(ctx, entry);
  });
  const tool = (m) => client.request('tool', m);
  // The dialogs are a bundle of their own (`wizard.js` beside `app.js`),
  // fetched when one first opens, with what the page shows at the click.
  const dialog = (name, args) => import(new URL('wizard.js', import.meta.url).href).then((w) => w[name](args)).catch((e) => toast(e.message));
  $('wizard').addEventListener('click', () => dialog('openWizard', { request: tool, t, dialect: state.dialect, onOpen: openText }));
  $('expand').addEventListener('click', () => dialog('openExpand', { request: tool, t, dialects: ctx.dialects, dialect: state.dialect, alarms: ctx.result()?.alarms ?? 0, onOpen: openText }));
  $('settings-form').addEventListener('submit', (e) => e.preventDefault());
  $('settings-reset').addEventListener('click', async () => {
    state.settings[state.dialect] = {};
    await ctx.buildSettings();
    ctx.persist();
    ctx.replan();
  });
  $('settings-close').addEventListener('click', () => $('settings-toggle').click());
  $('settings-toggle').addEventListener('click', () => {
    $('settings').hidden = !$('settings').hidden;
    $('settings-toggle').setAttribute('aria-pressed', String(!$('settings').hidden));
  });
  $('share').addEventListener('click', () => shareLink(encodeFragment(state), t));
  bindFileMenu(ctx, openText);
}

/** The File menu: open, save, print, the plan as JSON; it closes once an item is chosen, or on a click elsewhere. */
function bindFileMenu(ctx, openText) {
  const { state } = ctx;
  $('file-menu').addEventListener('click', (e) => {
    if (e.target.closest('.items button')) $('file-menu').open = false;
  });
  document.addEventListener('click', (e) => {
    if (!e.target.closest('#file-menu')) $('file-menu').open = false;
  });
  $('file-open').addEventListener('click', () => $('file-input').click());
  $('file-input').addEventListener('change', async (e) => {
    const file = e.target.files && e.target.files[0];
    e.target.value = '';
    await openFile(file, { dialect: state.dialect, t, say: toast, open: ({ dialect, program }) => openText({ dialect, text: program }) });
  });
  $('file-save').addEventListener('click', () => {
    const text = ctx.editor().text();
    download(fileName(text, state.dialect), new Blob([text], { type: 'text/plain;charset=utf-8' }));
  });
  $('print').addEventListener('click', () => window.print());
  window.addEventListener('beforeprint', () => fillPrintSheet($('print-sheet'), { text: ctx.editor().text(), result: ctx.result(), thread: ctx.thread(), t }));
  $('plan-json').addEventListener('click', async () => {
    const json = await ctx.client.request('json');
    download('screwcut-plan.json', new Blob([json], { type: 'application/json' }));
  });
}
