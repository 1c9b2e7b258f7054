// Browser test of what must never be lost and what must never do harm:
// node safety.test.mjs http://127.0.0.1:PORT/
//
// - The program list: a link opens as a new entry, the program that was
//   open stays and can be reopened, an entry can be deleted (and the
//   deletion undone), the list survives a reload; the one program of
//   earlier versions (`screwcut.state.v1`) becomes the list's first entry;
//   old `#j=`/`#z=` links still open; a full list and a tab without storage
//   say so and keep working.
// - Hostile links: a 400 KB `#z=` that inflates to 300 MB is refused with a
//   message (nothing replaced); a link with limits.diagnostics=1000000 and
//   200,000 lines of Y1 is clamped to the default limit, which is what the
//   planner gets, and says so; a link with an unknown controller, followed
//   in a tab that has the app open, opens as GSK980TDc with a message and
//   keystrokes still plan; a kept entry with an unknown controller too.
// - <screwcut-preview>: `app="javascript:…"` is not used (the link goes to
//   the default app) and is listed; `src` is fetched without cookies (seen
//   by route interception), a too-large or non-http `src` is refused in
//   the element; unknown dialect and bad `settings=` entries are listed;
//   the element folder of `cargo xtask dist`, copied next to a page of
//   another site as the element's README says, opens its app from "Open in editor".
// Timings are not asserted. Screenshots go to tests/browser/screenshots/.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';

const base = siteUrl('safety.test.mjs');
const { check, counts } = checker();
const timer = guard(240, 'the safety test');

const zfrag = (state) => '#z=' + zlib.deflateRawSync(Buffer.from(JSON.stringify(state)), { level: 9 }).toString('base64url');
const jfrag = (state) => '#j=' + Buffer.from(JSON.stringify(state)).toString('base64url');

/** A `#z=` link whose JSON inflates to `mib` MiB (a program of one repeated letter). */
async function bombFragment(mib) {
  const chunks = [];
  const z = zlib.createDeflateRaw({ level: 9 });
  z.on('data', (c) => chunks.push(c));
  const done = new Promise((resolve) => z.on('end', resolve));
  z.write('{"dialect":"gsk980tdc","settings":{},"program":"');
  const block = Buffer.alloc(1 << 20, 'G');
  for (let i = 0; i < mib; i++) if (!z.write(block)) await new Promise((resolve) => z.once('drain', resolve));
  z.end('"}');
  await done;
  return '#z=' + Buffer.concat(chunks).toString('base64url');
}

const problems = [];
const watch = (p, what) => {
  p.on('pageerror', (e) => problems.push(`${what}: pageerror ${e.message}`));
  p.on('console', (m) => m.type() === 'error' && problems.push(`${what}: console ${m.text()}`));
  p.on('dialog', (d) => {
    problems.push(`${what}: a dialog opened (${d.message()})`);
    d.dismiss().catch(() => {});
  });
};

const ready = (page) => page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
/** The app's list, open entry, editor text, notices, controller menu and probe errors. */
const app = (page) =>
  page.evaluate(() => {
    const p = window.__screwcut;
    const lib = p.library;
    return {
      list: lib.programs.list().map((i) => ({ id: i.id, name: i.name })),
      current: lib.current && { ...lib.current },
      unkept: [...lib.unkept.keys()],
      options: [...document.querySelectorAll('#programs option')].map((o) => ({ value: o.value, text: o.textContent })),
      chosen: document.getElementById('programs').value,
      text: p.text(),
      dialect: p.dialect(),
      dialectMenu: { value: document.getElementById('dialect').value, options: document.querySelectorAll('#dialect option').length },
      settings: lib.getState().settings,
      notices: [...document.querySelectorAll('#notices .notice')].map((n) => `${n.dataset.kind}: ${n.querySelector('.text').textContent}`),
      flag: document.getElementById('programs-state').hidden ? '' : document.getElementById('programs-state').textContent,
      errors: p.errors,
      hash: location.hash,
      updates: p.updates.length,
    };
  });
const clearNotices = (page) => page.evaluate(() => document.querySelectorAll('#notices .notice').forEach((n) => n.remove()));
/** Waits until the browser's storage holds `text` in some entry. */
const savedWith = (page, text) =>
  page.waitForFunction((t) => Object.keys(localStorage).some((k) => k.startsWith('screwcut.program.v1.') && (localStorage.getItem(k) || '').includes(t)), text, { timeout: 5_000 }).catch(() => {});
/** Opens the app at a link in a fresh load (not a hashchange of an open app). */
async function openLink(page, fragment) {
  await page.goto('about:blank');
  await page.goto(base + fragment);
  await ready(page);
}
/** Types `text` at the end of the program. */
async function typeAtEnd(page, text) {
  await page.locator('.cm-content').click();
  await page.keyboard.press('Control+End');
  await page.keyboard.type(text, { delay: 5 });
}

const { context, close } = await launch('screwcut-safety-', { viewport: { width: 1400, height: 900 } });
let server = null;
// Pages other than the app (a favicon.svg opened to reach the origin's storage, the vendored guide) make Chromium ask for /favicon.ico.
await context.route('**/favicon.ico', (route) => route.fulfill({ status: 204, body: '' }));
try {
  const page = context.pages()[0] || (await context.newPage());
  watch(page, 'app');

  // ---- the program list: a link opens as a new entry, the old one stays ----
  await page.goto(base);
  await ready(page);
  await page.waitForFunction(() => window.__screwcut.text().includes('O1006'));
  let s = await app(page);
  check('a fresh browser starts with one program, O1006, open', s.list.length === 1 && s.list[0].name === 'O1006' && s.chosen === s.current.id, JSON.stringify(s.list));
  await typeAtEnd(page, '\n(MY OWN WORK)');
  await savedWith(page, 'MY OWN WORK');
  const mine = (await app(page)).current.id;

  const linked = { dialect: 'fanuc0i', settings: { fanuc0i: { 5130: '5' } }, program: 'O4242 (FROM A LINK)\nG00 X40. Z5.\nG92 X38. Z-20. F1.5\nX37.4\nG00 X100. Z100.\nM30\n' };
  await openLink(page, zfrag(linked));
  s = await app(page);
  check('a link opens as a new entry', s.list.length === 2 && s.current.id !== mine && s.text === linked.program && s.dialect === 'fanuc0i', JSON.stringify({ list: s.list, text: s.text.slice(0, 30) }));
  check('… named by its O number and first comment, shown as the open one', s.current.name === 'O4242 FROM A LINK' && s.chosen === s.current.id && s.options.some((o) => o.text === 'O4242 FROM A LINK'), JSON.stringify(s.options));
  check('… says so, and the link is taken off the address', s.notices.some((n) => n.includes('new program')) && s.hash === '', JSON.stringify([s.notices, s.hash]));
  await page.screenshot({ path: path.join(shots, 'safety-link-new-entry.png') });
  const fromLink = s.current.id;
  await page.selectOption('#programs', mine);
  await page.waitForFunction(() => window.__screwcut.text().includes('MY OWN WORK'), null, { timeout: 5_000 }).catch(() => {});
  s = await app(page);
  check('the program open before the link is still there and reopens', s.current.id === mine && s.text.includes('O1006') && s.text.includes('(MY OWN WORK)') && s.dialect === 'gsk980tdc', s.text.slice(-40));
  await page.reload();
  await ready(page);
  s = await app(page);
  check('a reload keeps the list and the entry this tab had open', s.list.length === 2 && s.current.id === mine && s.text.includes('(MY OWN WORK)'), JSON.stringify(s.list));

  // Delete the linked entry (open it first), undo, delete again.
  await page.selectOption('#programs', fromLink);
  await page.waitForFunction(() => window.__screwcut.text().includes('FROM A LINK'));
  await clearNotices(page);
  await page.click('#program-delete');
  await page.waitForFunction((id) => !window.__screwcut.library.programs.list().some((i) => i.id === id), fromLink, { timeout: 5_000 }).catch(() => {});
  s = await app(page);
  check('Delete removes the open entry and opens the other one', s.list.length === 1 && s.list[0].id === mine && s.current.id === mine && s.text.includes('MY OWN WORK'), JSON.stringify(s.list));
  check('… with an Undo in its message', s.notices.some((n) => n.includes('Deleted') && n.includes('O4242')) && (await page.locator('#notices .notice button.action').count()) === 1, JSON.stringify(s.notices));
  await page.screenshot({ path: path.join(shots, 'safety-deleted-undo.png') });
  await page.click('#notices .notice button.action');
  await page.waitForFunction(() => window.__screwcut.text().includes('FROM A LINK'), null, { timeout: 5_000 }).catch(() => {});
  s = await app(page);
  check('Undo brings the entry back, open', s.list.length === 2 && s.current.id === fromLink && s.text === linked.program, JSON.stringify(s.list));
  await page.click('#program-delete');
  await page.waitForFunction(() => window.__screwcut.library.programs.list().length === 1, null, { timeout: 5_000 }).catch(() => {});
  await page.reload();
  await ready(page);
  s = await app(page);
  check('a deletion survives a reload', s.list.length === 1 && s.list[0].id === mine && s.text.includes('MY OWN WORK'), JSON.stringify(s.list));

  // ---- old links: #j= as embeds write it, #z= as "Copy link" wrote it ----
  const oldJ = { dialect: 'renhe', settings: { renhe: {} }, program: '(OLD J LINK)\nG00 X50 Z10\nG00 U-16\nG33 W-40 F1.5\n' };
  await openLink(page, jfrag(oldJ));
  s = await app(page);
  check('an old #j= link opens (as a new entry)', s.text === oldJ.program && s.dialect === 'renhe' && s.list.length === 2, JSON.stringify({ d: s.dialect, n: s.list.length }));
  const oldZ = { dialect: 'gsk980tdc', settings: { gsk980tdc: { 'No.019': '5' } }, program: 'O0777 (OLD Z LINK)\nG00 X30 Z5\nG92 X23.2 Z-30 F3 L2\nX22.6\n', lang: 'en' };
  await openLink(page, zfrag(oldZ));
  s = await app(page);
  check('an old #z= link opens (as a new entry, its settings kept)', s.text === oldZ.program && s.list.length === 3 && s.settings.gsk980tdc['No.019'] === '5', JSON.stringify({ n: s.list.length, settings: s.settings }));
  await openLink(page, zfrag(oldZ));
  s = await app(page);
  check('the same link again opens the kept entry, not a copy', s.list.length === 3 && s.notices.some((n) => n.includes('already kept')), JSON.stringify(s.notices));

  // ---- hostile: a 400 KB link that inflates to 300 MB ----
  const before = await app(page);
  const bomb = await bombFragment(300);
  console.log(`the bomb link: ${bomb.length.toLocaleString('en')} characters, inflating to 300 MiB`);
  await openLink(page, bomb);
  s = await app(page);
  check('a #z= bomb is refused with a message', s.notices.some((n) => n.startsWith('error') && n.includes('not opened') && n.includes('8 MiB')), JSON.stringify(s.notices));
  check('… nothing replaced: the same entries and the same open program', s.list.length === before.list.length && s.current.id === before.current.id && s.text === before.text, JSON.stringify({ n: s.list.length, text: s.text.slice(0, 30) }));
  check('… and the link is taken off the address', s.hash === '' && s.errors.length === 0, JSON.stringify([s.hash.slice(0, 20), s.errors]));
  await page.screenshot({ path: path.join(shots, 'safety-bomb-refused.png') });
  // The same bomb followed in the open tab (hashchange).
  await clearNotices(page);
  await page.evaluate((h) => (location.hash = h), bomb);
  await page.waitForSelector('#notices .notice.error', { timeout: 10_000 }).catch(() => {});
  s = await app(page);
  check('… also when followed in a tab that has the app open', s.notices.some((n) => n.includes('more than 8 MiB')) && s.current.id === before.current.id && s.text === before.text && s.hash === '', JSON.stringify(s.notices));
  await openLink(page, '#j=' + Buffer.from('[1,2,3]').toString('base64url'));
  s = await app(page);
  check('a link without a program is refused with a message', s.notices.some((n) => n.includes('carries no program')) && s.list.length === before.list.length, JSON.stringify(s.notices));

  // ---- hostile: limits.diagnostics=1000000 and 200,000 lines of Y1 ----
  const flood = {
    dialect: 'gsk980tdc',
    settings: { gsk980tdc: { 'limits.diagnostics': '1000000', 'LIMITS.moves': '1e8', 'limits.digits': '6', 'x=1\nlimits.starts': '9' } },
    program: 'O0200 (Y FLOOD)\n' + 'Y1\n'.repeat(200_000),
  };
  const floodLink = zfrag(flood);
  console.log(`the flood link: ${floodLink.length.toLocaleString('en')} characters, ${flood.program.length.toLocaleString('en')} characters of program`);
  const tFlood = Date.now();
  await openLink(page, floodLink);
  await page.waitForFunction(() => window.__screwcut.result && window.__screwcut.result.alarms > 0, null, { timeout: 60_000 });
  const floodMs = Date.now() - tFlood;
  s = await app(page);
  const got = s.settings.gsk980tdc || {};
  check('limits.diagnostics=1000000 from a link is clamped to its default, 1000', got['limits.diagnostics'] === '1000', JSON.stringify(got));
  check('… limits.moves=1e8 too; a lower limit (limits.digits=6) is kept', got['LIMITS.moves'] === '10000000' && got['limits.digits'] === '6', JSON.stringify(got));
  check('… a setting name with a line break (a second NAME=VALUE in disguise) is dropped', !Object.keys(got).some((k) => k.includes('\n')), JSON.stringify(Object.keys(got)));
  check('… and the page says what was clamped', s.notices.some((n) => n.includes('limits.diagnostics 1000000 → 1000') && n.includes('LIMITS.moves') || n.includes('limits.moves')), JSON.stringify(s.notices));
  const planned = await page.evaluate(() => ({ diagnostics: window.__screwcut.result.diagnostics.length, field: document.querySelector('[data-name="limits.diagnostics"] input')?.value }));
  check('the planner got the clamped limit: at most 1000 diagnostics listed', planned.diagnostics <= 1001 && planned.diagnostics >= 900 && planned.field === '1000', JSON.stringify(planned));
  await page.screenshot({ path: path.join(shots, 'safety-limits-clamped.png') });
  const u0 = (await app(page)).updates;
  await page.locator('.cm-line').first().click();
  await page.keyboard.press('End');
  await page.keyboard.type(' X', { delay: 20 });
  await page.waitForFunction((n) => window.__screwcut.updates.length > n, u0, { timeout: 60_000 }).catch(() => {});
  s = await app(page);
  check('… and keystrokes in it re-plan', s.updates > u0 && s.errors.length === 0, JSON.stringify({ before: u0, after: s.updates, errors: s.errors }));
  const lastPlan = await page.evaluate(() => window.__screwcut.updates.at(-1));
  console.log(`the flood link: planned and listed ${floodMs} ms after navigation; a keystroke re-planned in ${lastPlan.plan.toFixed(0)} ms in the worker (printed, not asserted)`);

  // ---- hostile: an unknown controller, followed in a tab that has the app open ----
  await page.goto(base);
  await ready(page);
  await clearNotices(page);
  const n0 = (await app(page)).list.length;
  await page.evaluate((h) => (location.hash = h), jfrag({ dialect: 'bogus9000', settings: { bogus9000: { x: '1' } }, program: '(UNKNOWN CONTROLLER)\nG00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n' }));
  await page.waitForFunction(() => window.__screwcut.text().includes('UNKNOWN CONTROLLER'), null, { timeout: 10_000 }).catch(() => {});
  s = await app(page);
  check('an unknown controller link in an open tab opens as a new entry, as GSK980TDc', s.list.length === n0 + 1 && s.dialect === 'gsk980tdc' && s.dialectMenu.value === 'gsk980tdc' && s.dialectMenu.options >= 3, JSON.stringify({ n: s.list.length, d: s.dialect, menu: s.dialectMenu }));
  check('… and says so', s.notices.some((n) => n.includes("unknown controller 'bogus9000'")), JSON.stringify(s.notices));
  await page.screenshot({ path: path.join(shots, 'safety-unknown-dialect.png') });
  const u1 = s.updates;
  await typeAtEnd(page, '\nX46.5\nG32 Z13\n');
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 2, null, { timeout: 10_000 }).catch(() => {});
  s = await app(page);
  check('… keystrokes plan without an error', s.updates > u1 && s.errors.length === 0 && (await page.locator('#passes tbody tr[data-pass]').count()) === 2, JSON.stringify({ errors: s.errors, updates: s.updates }));

  // A kept entry with an unknown controller (as some other version might have written it).
  await clearNotices(page);
  await page.evaluate(() => {
    const e = { name: 'O0666', dialect: 'nonesuch', settings: { nonesuch: { a: '1' } }, program: 'O0666 (ODD CONTROLLER)\nG00 X58 Z70\n', created: Date.now(), updated: Date.now() };
    const json = JSON.stringify(e);
    localStorage.setItem('screwcut.program.v1.tampered', json);
    const index = JSON.parse(localStorage.getItem('screwcut.programs.v1'));
    index.push({ id: 'tampered', name: e.name, dialect: e.dialect, created: e.created, updated: e.updated, size: json.length });
    localStorage.setItem('screwcut.programs.v1', JSON.stringify(index));
    window.__screwcut.library.render();
  });
  await page.selectOption('#programs', 'tampered');
  await page.waitForFunction(() => window.__screwcut.text().includes('ODD CONTROLLER'), null, { timeout: 5_000 }).catch(() => {});
  s = await app(page);
  check('a kept entry with an unknown controller opens as GSK980TDc and says so', s.dialect === 'gsk980tdc' && s.dialectMenu.value === 'gsk980tdc' && s.notices.some((n) => n.includes('nonesuch')) && s.errors.length === 0, JSON.stringify({ d: s.dialect, notices: s.notices }));
  await typeAtEnd(page, '\nX47.1');
  await page.waitForTimeout(300);
  check('… and keystrokes plan without an error', (await app(page)).errors.length === 0);

  // ---- the one program of earlier versions becomes the first entry ----
  const legacy = await context.newPage();
  watch(legacy, 'legacy');
  await legacy.goto(base + 'favicon.svg');
  await legacy.evaluate(() => {
    localStorage.clear();
    sessionStorage.clear();
    localStorage.setItem('screwcut.state.v1', JSON.stringify({ dialect: 'fanuc0i', settings: { fanuc0i: { 5130: '10' } }, program: 'O0555 (KEPT BY AN OLD VERSION)\nG00 X40. Z5.\n', lang: 'zh' }));
  });
  await legacy.goto(base);
  await ready(legacy);
  s = await app(legacy);
  const left = await legacy.evaluate(() => localStorage.getItem('screwcut.state.v1'));
  check('screwcut.state.v1 is read: its program is the first entry, open', s.list.length === 1 && s.text.startsWith('O0555 (KEPT BY AN OLD VERSION)') && s.dialect === 'fanuc0i' && s.settings.fanuc0i['5130'] === '10', JSON.stringify({ list: s.list, d: s.dialect }));
  check('… with its language; the old key is gone once moved', (await legacy.evaluate(() => document.documentElement.lang)) === 'zh-CN' && left === null, String(left));
  await legacy.screenshot({ path: path.join(shots, 'safety-migrated-zh.png') });
  await legacy.evaluate(() => localStorage.setItem('screwcut.prefs.v1', JSON.stringify({ lang: 'en' })));
  await legacy.close();

  // ---- a full list: the link opens, is not kept, says so; kept once there is room ----
  const full = await context.newPage();
  watch(full, 'full');
  await full.goto(base + 'favicon.svg');
  await full.evaluate(() => {
    localStorage.clear();
    sessionStorage.clear();
    const index = [];
    for (let i = 0; i < 50; i++) {
      const e = { name: `O${1000 + i}`, dialect: 'gsk980tdc', settings: {}, program: `O${1000 + i}\nG00 X10 Z10\n`, created: 1e12 + i, updated: 1e12 + i };
      const json = JSON.stringify(e);
      localStorage.setItem(`screwcut.program.v1.p${i}`, json);
      index.push({ id: `p${i}`, name: e.name, dialect: e.dialect, created: e.created, updated: e.updated, size: json.length });
    }
    localStorage.setItem('screwcut.programs.v1', JSON.stringify(index));
  });
  const extra = { dialect: 'gsk980tdc', settings: {}, program: 'O9999 (ONE TOO MANY)\nG00 X58 Z70\n' };
  await full.goto(base + zfrag(extra));
  await ready(full);
  s = await app(full);
  check('a link into a full list (50 programs) opens, marked not kept, and says so', s.text === extra.program && s.list.length === 50 && !s.current.kept && s.flag === 'not kept' && s.notices.some((n) => n.includes('full') && n.includes('50 of 50')), JSON.stringify({ n: s.list.length, flag: s.flag, notices: s.notices }));
  check('… the menu lists it as not kept', s.options[0].text.includes('O9999') && s.options[0].text.includes('not kept') && s.chosen === s.current.id, JSON.stringify(s.options.slice(0, 2)));
  await full.screenshot({ path: path.join(shots, 'safety-full.png') });
  // Open another program (the unkept one stays for this tab), delete it: the unkept one is kept now.
  const unkeptId = s.current.id;
  await full.selectOption('#programs', 'p3');
  await full.waitForFunction(() => window.__screwcut.text().startsWith('O1003'));
  await full.click('#program-delete');
  await full.waitForFunction((id) => window.__screwcut.library.programs.list().some((i) => i.id === id), unkeptId, { timeout: 5_000 }).catch(() => {});
  s = await app(full);
  check('… deleting another program makes room: it is kept now', s.list.some((i) => i.id === unkeptId) && s.list.length === 50 && s.unkept.length === 0 && s.notices.some((n) => n.includes('kept now')), JSON.stringify({ n: s.list.length, unkept: s.unkept, notices: s.notices }));
  await full.selectOption('#programs', unkeptId);
  await full.waitForFunction(() => window.__screwcut.text().includes('ONE TOO MANY'), null, { timeout: 5_000 }).catch(() => {});
  check('… and reopens', (await app(full)).text === extra.program);
  await full.close();

  // ---- a tab without storage (private mode) ----
  const priv = await context.newPage();
  watch(priv, 'private');
  await priv.addInitScript(() => {
    for (const name of ['localStorage', 'sessionStorage']) {
      Object.defineProperty(window, name, {
        get() {
          throw new DOMException('The page may not store data', 'SecurityError');
        },
      });
    }
  });
  await priv.goto(base + zfrag({ dialect: 'gsk980tdc', settings: {}, program: 'O0123 (PRIVATE)\nG00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n' }));
  await ready(priv);
  await priv.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 1, null, { timeout: 10_000 }).catch(() => {});
  s = await app(priv);
  check('without storage the app opens the link and plans it', s.text.includes('PRIVATE') && (await priv.locator('#passes tbody tr[data-pass]').count()) === 1 && s.errors.length === 0, JSON.stringify(s.errors));
  check('… and says programs are not kept', s.flag.includes('not kept') && s.notices.some((n) => n.includes('does not let the page keep data')), JSON.stringify({ flag: s.flag, notices: s.notices }));
  await priv.screenshot({ path: path.join(shots, 'safety-private.png') });
  await priv.close();

  // ---- <screwcut-preview>: hostile attributes ----
  await context.addCookies([{ name: 'session', value: 'secret-cookie', url: base }]);
  const seenHeaders = {};
  const embed = await context.newPage();
  watch(embed, 'embed');
  const program = 'G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n';
  await embed.route(`${base}safety/**`, async (route) => {
    const url = new URL(route.request().url());
    const file = url.pathname.split('/').pop();
    if (file === 'page.html') {
      return route.fulfill({
        contentType: 'text/html; charset=utf-8',
        body: `<!doctype html><meta charset="utf-8"><title>embed safety</title>
<script type="module" src="../screwcut-preview.js"></script>
<screwcut-preview id="js-app" app="javascript:alert(document.domain)//">${program}</screwcut-preview>
<screwcut-preview id="bad-dialect" dialect="bogus">${program}</screwcut-preview>
<screwcut-preview id="alias" dialect="Fanuc">${program}</screwcut-preview>
<screwcut-preview id="bad-settings" settings="No.019=5; nonsense; frobnicate=3; limits.diagnostics=abc">${program}</screwcut-preview>
<screwcut-preview id="src-ok" src="prog.nc"></screwcut-preview>
<screwcut-preview id="src-big" src="big.nc"></screwcut-preview>
<screwcut-preview id="src-data" src="data:text/plain,G00%20X1"></screwcut-preview>`,
      });
    }
    seenHeaders[file] = await route.request().allHeaders();
    if (file === 'prog.nc' || file === 'control.nc') return route.fulfill({ contentType: 'text/plain', body: program });
    if (file === 'big.nc') return route.fulfill({ contentType: 'text/plain', body: 'G00 X1 Z1\n'.repeat(220_000) });
    return route.fulfill({ status: 404, body: 'not found' });
  });
  await embed.goto(`${base}safety/page.html`);
  await embed.evaluate(() => customElements.whenDefined('screwcut-preview'));
  await embed.evaluate(() => Promise.all([...document.querySelectorAll('screwcut-preview')].map((e) => e.start())));
  await embed.waitForFunction(() => [...document.querySelectorAll('screwcut-preview')].every((e) => ['ready', 'error'].includes(e.dataset.state)), null, { timeout: 30_000 });
  await embed.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const el = (id) =>
    embed.evaluate((id) => {
      const e = document.getElementById(id);
      const root = e.shadowRoot;
      return {
        state: e.dataset.state,
        href: root.querySelector('a.open').href,
        problems: e.problems,
        listed: [...root.querySelectorAll('ul.diags li.problem')].map((li) => li.textContent),
        summary: root.querySelector('.sum').textContent,
        dialect: e.result && e.result.dialect,
        threads: e.result ? e.result.threads.length : -1,
        program: e.program,
      };
    }, id);
  let e = await el('js-app');
  check('app="javascript:…" is not the link: it opens the default app', e.href.startsWith(base + '#j=') && !e.href.startsWith('javascript'), e.href.slice(0, 60));
  check('… and the element lists why', e.listed.some((t) => t.startsWith('app') && t.includes('not an http(s) or relative URL')) && e.problems.some((p) => p.attribute === 'app'), JSON.stringify(e.listed));
  await embed.locator('#js-app').screenshot({ path: path.join(shots, 'safety-embed-js-app.png') });
  e = await el('bad-dialect');
  check('dialect="bogus" plans as gsk980tdc and is listed', e.state === 'ready' && e.dialect === 'gsk980tdc' && e.threads === 1 && e.listed.some((t) => t.startsWith('dialect') && t.includes('bogus')), JSON.stringify(e));
  e = await el('alias');
  check('dialect="Fanuc" (a spelling the planner accepts) plans as fanuc0i, nothing listed', e.dialect === 'fanuc0i' && e.listed.length === 0, JSON.stringify(e));
  e = await el('bad-settings');
  const said = e.listed.join(' | ');
  check('settings= entries that are not NAME=VALUE or that the planner refuses are listed', said.includes("'nonsense' is not NAME=VALUE") && said.includes('frobnicate') && said.includes('limits.diagnostics') && e.listed.length === 3, said);
  await embed.locator('#bad-settings').screenshot({ path: path.join(shots, 'safety-embed-settings.png') });
  e = await el('src-ok');
  check('src= loads the program', e.state === 'ready' && e.program === program && e.threads === 1, JSON.stringify(e));
  await embed.evaluate(() => fetch('control.nc').then((r) => r.text()));
  check('src= is fetched without cookies (a plain fetch from the page sends them)', seenHeaders['prog.nc'] && !('cookie' in seenHeaders['prog.nc']) && (seenHeaders['control.nc'] || {}).cookie === 'session=secret-cookie', JSON.stringify({ src: seenHeaders['prog.nc'], control: seenHeaders['control.nc'] && seenHeaders['control.nc'].cookie }));
  e = await el('src-big');
  check('a src= over 1 MiB is refused in the element', e.state === 'error' && e.summary.includes('larger than 1 MiB') && e.threads === -1, e.summary);
  await embed.locator('#src-big').screenshot({ path: path.join(shots, 'safety-embed-src-big.png') });
  e = await el('src-data');
  check('a src= that is not http(s) is refused in the element', e.state === 'error' && e.summary.includes('not an http(s) or relative URL') && !('data:text' in seenHeaders), e.summary);
  await embed.close();

  // ---- the element folder vendored next to another site's page, as the element's README says ----
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'screwcut-vendored-'));
  const folder = path.join(dir, 'guide', 'element');
  fs.mkdirSync(path.join(folder, 'examples'), { recursive: true });
  const pkg = await (await fetch(`${base}element/package.json`)).json();
  const files = pkg.files.filter((f) => !f.endsWith('/'));
  const examples = await (await fetch(`${base}element/examples/index.json`)).json();
  files.push('examples/index.json', ...examples.map((x) => `examples/${x.file}`));
  for (const f of files) {
    const r = await fetch(`${base}element/${f}`);
    if (!r.ok) throw new Error(`element/${f}: ${r.status}`);
    fs.writeFileSync(path.join(folder, f), Buffer.from(await r.arrayBuffer()));
  }
  fs.writeFileSync(
    path.join(dir, 'guide', 'index.html'),
    `<!doctype html><meta charset="utf-8"><title>Our threading guide</title><h1>Our guide</h1>
<script type="module" src="element/screwcut-preview.js"></script>

<screwcut-preview id="streamed" src="stream.nc" view="side"></screwcut-preview>

<screwcut-preview id="vendored" dialect="gsk980tdc" view="side table" height="300">
G00 X58 Z70
X47.1
G32 Z13 F2
G00 X58
Z70
</screwcut-preview>
`,
  );
  const types = { html: 'text/html; charset=utf-8', js: 'text/javascript', wasm: 'application/wasm', json: 'application/json', css: 'text/css', svg: 'image/svg+xml', nc: 'text/plain', md: 'text/markdown' };
  let streamed = null; // bytes the server had sent of a 64 MiB src when the element hung up
  server = http.createServer((req, res) => {
    let p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (p === '/guide/stream.nc') {
      // 64 MiB without a Content-Length (chunked): only reading the stream can stop it.
      const chunk = Buffer.from('G00 X1 Z1\n'.repeat(6554));
      let sent = 0;
      res.writeHead(200, { 'Content-Type': 'text/plain' });
      res.on('close', () => (streamed = sent));
      const pump = () => {
        while (sent < 64 << 20 && !res.destroyed) {
          sent += chunk.length;
          if (!res.write(chunk)) return void res.once('drain', pump);
        }
        res.end();
      };
      pump();
      return;
    }
    if (p.endsWith('/')) p += 'index.html';
    const file = path.join(dir, p);
    if (!file.startsWith(dir) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found');
      return;
    }
    res.writeHead(200, { 'Content-Type': types[path.extname(file).slice(1)] || 'application/octet-stream' }).end(fs.readFileSync(file));
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  const other = `http://127.0.0.1:${server.address().port}/`;
  const guide = await context.newPage();
  watch(guide, 'vendored');
  await guide.goto(`${other}guide/`);
  await guide.waitForFunction(() => document.getElementById('vendored').dataset.state === 'ready', null, { timeout: 30_000 });
  await guide.evaluate(() => document.getElementById('streamed').start());
  await guide.waitForFunction(() => document.getElementById('streamed').dataset.state !== 'loading', null, { timeout: 30_000 });
  for (let i = 0; i < 50 && streamed === null; i++) await guide.waitForTimeout(100);
  const st = await guide.evaluate(() => ({ state: document.getElementById('streamed').dataset.state, sum: document.getElementById('streamed').shadowRoot.querySelector('.sum').textContent }));
  check('a src= streamed without a length stops reading past 1 MiB', st.state === 'error' && st.sum.includes('larger than 1 MiB') && streamed !== null && streamed < 64 << 20, JSON.stringify({ ...st, streamed }));
  const href = await guide.evaluate(() => document.getElementById('vendored').shadowRoot.querySelector('a.open').href);
  check('vendored: "Open in editor" points at the app in the element folder', href.startsWith(`${other}guide/element/#j=`), href.slice(0, 70));
  const [opened] = await Promise.all([context.waitForEvent('page'), guide.locator('#vendored a.open').click()]);
  watch(opened, 'vendored app');
  await opened.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  const there = await opened.evaluate(() => ({ text: window.__screwcut.text(), rows: document.querySelectorAll('#passes tbody tr[data-pass]').length, title: document.title }));
  check('… and the app opens there with the program', there.text === 'G00 X58 Z70\nX47.1\nG32 Z13 F2\nG00 X58\nZ70\n' && there.rows === 1 && there.title.startsWith('screwcut'), JSON.stringify(there));
  await opened.screenshot({ path: path.join(shots, 'safety-vendored-app.png') });
  await opened.close();
  await guide.close();
  fs.rmSync(dir, { recursive: true, force: true });

  check('no page error, console error or dialog', problems.length === 0, JSON.stringify(problems.slice(0, 8)));
} catch (err) {
  check('the safety test ran to the end', false, err && err.stack ? err.stack : String(err));
} finally {
  clearTimeout(timer);
  if (server) server.close();
  await close();
}

finish('safety', counts);
