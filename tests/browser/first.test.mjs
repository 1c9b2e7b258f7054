// Browser test: a first visit's first diagram comes with the page.
// node first.test.mjs http://127.0.0.1:PORT/
//
// 1. A first visit (a new profile): with the app's script held back, the
//    page alone shows the example O1006 — its program in the editor's
//    place and its three drawings in the views' places, painted — and
//    asks for nothing else to show them. Once the script runs, the app's
//    own drawings and editor take their places and the page's are gone.
// 2. The next visit (the example is now a kept program) shows none of
//    them: what it opens is the kept program, drawn by the app. Nor does
//    a visit with a kept entry whose index line was lost (the app
//    recovers and opens it).
// 3. Nor a visit by a link (the app opens the link's program). A first
//    visit in Chinese shows the drawings with Chinese labels. In either
//    language the page's own words (every text, title and placeholder it
//    names, the title, the language) are before the app's script what
//    the app then writes.
// Screenshots: first-static.png (1400×900, the script held back),
// first-static-390.png (a phone, the same), first-static-zh.png (in
// Chinese) and first-live.png (1400×900, the app drawn) in
// tests/browser/screenshots/.

import { siteUrl, checker, guard, launch, finish, shots } from './harness.mjs';
import fs from 'node:fs';
import path from 'node:path';

const url = siteUrl('first.test.mjs');
const { check, counts } = checker();
const timer = guard(180, 'the first-visit test');
const problems = [];
const O1006 = fs.readFileSync(new URL('../../examples/o1006.nc', import.meta.url), 'utf8');

/** What of the page's first-visit parts shows: the class, the drawings (title and size) and the program. */
const shown = (page) =>
  page.evaluate(() => {
    const visible = (el) => el.getBoundingClientRect().height > 0 && getComputedStyle(el).display !== 'none';
    return {
      first: document.documentElement.classList.contains('first-visit'),
      zh: document.documentElement.classList.contains('first-zh'),
      drawings: [...document.querySelectorAll('.pane > .first')]
        .filter(visible)
        .map((d) => ({ title: d.querySelector('svg title')?.textContent, h: Math.round(d.getBoundingClientRect().height), covers: d.parentElement.querySelector('canvas').id, lang: d.classList.contains('zh') ? 'zh' : 'en', text: d.textContent })),
      code: [...document.querySelectorAll('#editor > pre.first')].filter(visible).map((p) => p.textContent),
      parts: document.querySelectorAll('.first').length,
    };
  });

/** The page's own words: each named word's text, title or placeholder (`[attribute, key, text]`), the title and the language. */
const words = (page) =>
  page.evaluate(() => {
    const named = [];
    const props = { 'data-i18n': 'textContent', 'data-i18n-title': 'title', 'data-i18n-placeholder': 'placeholder', 'data-program-word': 'textContent', 'data-program-title': 'title' };
    for (const [attr, prop] of Object.entries(props)) {
      for (const el of document.querySelectorAll(`[${attr}]`)) named.push([attr, el.getAttribute(attr), el[prop]]);
    }
    named.push(['#lang', '', document.getElementById('lang').textContent]);
    return { named, title: document.title, lang: document.documentElement.lang };
  });

/** The words of `before` (the page alone) that differ from `after` (the app's own), named by their keys; those the app replaced by others (the examples' first option) are not compared. */
const differ = (before, after) => {
  const of = new Map(after.named.map(([a, k, text]) => [`${a} ${k}`, text]));
  const d = before.named.filter(([a, k, text]) => of.has(`${a} ${k}`) && of.get(`${a} ${k}`) !== text).map(([a, k, text]) => `${a}=${k}: ${JSON.stringify(text)} (app: ${JSON.stringify(of.get(`${a} ${k}`))})`);
  if (before.title !== after.title) d.push(`title: ${before.title} (app: ${after.title})`);
  if (before.lang !== after.lang) d.push(`lang: ${before.lang} (app: ${after.lang})`);
  return d;
};

/** Opens the app in a new profile with `options` (locale …), the app's script held back until `release()`. */
async function held(prefix, options = {}) {
  const { context, close } = await launch(prefix, { viewport: { width: 1400, height: 900 }, ...options });
  const page = context.pages()[0] || (await context.newPage());
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  const requested = [];
  page.on('request', (r) => requested.push(new URL(r.url()).pathname));
  let release;
  const gate = new Promise((r) => {
    release = r;
  });
  await context.route('**/app.js', async (route) => {
    await gate;
    await route.continue();
  });
  return { context, page, close, requested, release };
}

try {
  // ---- 1. a first visit ----
  {
    const { page, close, requested, release } = await held('screwcut-first-');
    await page.goto(url, { waitUntil: 'commit' });
    await page.waitForFunction(() => document.querySelectorAll('.pane > .first svg').length === 8 && document.querySelector('.pane > .first').getBoundingClientRect().height > 100, null, { timeout: 20_000 });
    await page.waitForFunction(() => performance.getEntriesByType('paint').some((e) => e.name === 'first-contentful-paint'), null, { timeout: 20_000 });
    const s = await shown(page);
    check('1. a first visit holds the example: the page is marked first', s.first, JSON.stringify(s));
    check(
      '… its three drawings show in the views, over the canvases',
      s.drawings.map((d) => d.title).join('|') === 'screwcut: side section|screwcut: tooth section|screwcut: starts' && s.drawings.map((d) => d.covers).join() === 'side,tooth,starts' && s.drawings.every((d) => d.h > 150),
      JSON.stringify(s.drawings),
    );
    check('… and the program O1006 in the editor’s place, as the example file has it', s.code.length === 1 && s.code[0] === O1006, JSON.stringify(s.code[0]?.slice(0, 80)));
    // What the drawings were painted with: the page and its stylesheet, not the script or the wasm.
    const before = [...requested];
    const en = await words(page);
    check('… painted with the app’s script still held back, before any wasm was asked for', !before.some((p) => p.endsWith('.wasm')) && !before.includes('/worker.js'), before.join(' '));
    const sides = await page.evaluate(() => document.querySelector('.pane > .first svg').outerHTML);
    check('… the side drawing has the passes’ cuts drawn (the cut pen)', sides.includes('stroke="#2563eb"'), sides.slice(0, 120));
    const ids = await page.evaluate(() => [...document.querySelectorAll('.first [id]')].map((e) => e.id));
    check('… the drawings’ ids are unique in the page', ids.length >= 4 && new Set(ids).size === ids.length, ids.join(' '));
    // Nothing is counted before a plan: the diagnostics' counts are empty, not 0 (the example has two notes).
    const counts = await page.evaluate(() => [...document.querySelectorAll('#sev-filter .n')].map((n) => n.textContent));
    check('… the diagnostics’ counts say nothing before the plan (not “0”)', counts.length === 3 && counts.every((c) => c === ''), JSON.stringify(counts));
    // Where the header's controls, the drawings and the lists are laid out: the app's own must not move them
    // (its lists in the header and the footer's summary, filled in by the app, included).
    const places = () => page.evaluate(() => [...document.querySelectorAll('header select, header button, header summary, #views .view, #views .panel, #views aside, #code')].map((e) => [e.id || e.className, ...Object.values(e.getBoundingClientRect().toJSON()).slice(0, 4).map(Math.round)]));
    const placed = await places();
    await page.screenshot({ path: path.join(shots, 'first-static.png') });
    // On a phone the side section is the one laid out for its canvas, not the wide one shrunk.
    await page.setViewportSize({ width: 390, height: 844 });
    const phone = await page.evaluate(() =>
      [...document.querySelectorAll('.pane > .first')].filter((d) => getComputedStyle(d).display !== 'none').map((d) => ({ cls: d.className, w: Math.round(d.getBoundingClientRect().width), svg: Math.round(d.querySelector('svg').getBoundingClientRect().height) })),
    );
    check('… at 390 wide the side section shown is the narrow one, filling its view', phone.length === 3 && phone[0].cls === 'first narrow en' && phone[0].svg > 200, JSON.stringify(phone));
    await page.screenshot({ path: path.join(shots, 'first-static-390.png'), fullPage: true });
    await page.setViewportSize({ width: 1400, height: 900 });
    release();
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
    await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 30_000 });
    await page.waitForTimeout(300);
    const after = await shown(page);
    check('… once the app has drawn, its parts are gone and the canvases show', !after.first && after.parts === 0 && after.drawings.length === 0, JSON.stringify(after));
    const placedLive = await places();
    check('… the header’s controls, the views, the lists and the editor stay where the first visit laid them out', placed.length >= 16 && JSON.stringify(placed) === JSON.stringify(placedLive), `${JSON.stringify(placed)} → ${JSON.stringify(placedLive)}`);
    const live = await page.evaluate(() => [...document.querySelectorAll('#sev-filter .n')].map((n) => n.textContent));
    check('… and the app counts the plan’s diagnostics: 0 alarms, 0 warnings, 2 notes', JSON.stringify(live) === '["0","0","2"]', JSON.stringify(live));
    const editor = await page.evaluate(() => window.__screwcut.text());
    check('… and the editor holds the same program', editor === O1006, JSON.stringify(editor?.slice(0, 60)));
    const enApp = await words(page);
    check('… the page’s own words before the app’s script (texts, titles, placeholders) were the app’s English ones', en.named.length >= 25 && enApp.lang === 'en' && differ(en, enApp).length === 0, differ(en, enApp).join(' | '));
    await page.screenshot({ path: path.join(shots, 'first-live.png') });

    // ---- 2. the next visit ----
    const kept = await page.evaluate(() => localStorage.getItem('screwcut.programs.v1') !== null);
    check('2. the example is now a kept program', kept);
    await page.reload({ waitUntil: 'domcontentloaded' });
    const again = await shown(page);
    check('… the next visit shows none of the page’s first-visit parts', !again.first && again.drawings.length === 0 && again.code.length === 0, JSON.stringify(again));
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
    await close();
  }

  // ---- 2b. a kept entry whose index line was lost (the app recovers and opens it) ----
  {
    const { context, page, close, release } = await held('screwcut-first-lost-');
    await context.addInitScript(() => {
      if (!localStorage.getItem('screwcut.program.v1.lost1')) {
        const now = Date.now();
        localStorage.setItem('screwcut.program.v1.lost1', JSON.stringify({ id: 'lost1', dialect: 'fanuc0itf', settings: {}, program: 'O2000 (KEPT)\nG00 X50. Z5.\nM30\n', created: now, updated: now }));
      }
    });
    await page.goto(url, { waitUntil: 'commit' });
    await page.waitForFunction(() => document.querySelector('footer'), null, { timeout: 20_000 });
    const s = await shown(page);
    check('2b. a kept entry without its index line: none of them (the app opens that entry)', !s.first && s.drawings.length === 0 && s.code.length === 0, JSON.stringify(s));
    release();
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
    const text = await page.evaluate(() => window.__screwcut.text());
    check('… and the app did open it', text.startsWith('O2000 (KEPT)'), JSON.stringify(text?.slice(0, 40)));
    await close();
  }

  // ---- 3. a link; Chinese ----
  {
    const { page, close, release } = await held('screwcut-first-link-');
    await page.goto(`${url}#p=not-a-program`, { waitUntil: 'commit' });
    await page.waitForFunction(() => document.querySelector('footer'), null, { timeout: 20_000 });
    const s = await shown(page);
    check('3. a visit by a link shows none of them', !s.first && s.drawings.length === 0 && s.code.length === 0, JSON.stringify(s));
    release();
    await page.waitForSelector('body[data-ready]', { timeout: 60_000 });
    await close();
  }
  {
    const { page, close, release } = await held('screwcut-first-zh-', { locale: 'zh-CN' });
    await page.goto(url, { waitUntil: 'commit' });
    await page.waitForFunction(() => [...document.querySelectorAll('.pane > .first')].some((d) => d.getBoundingClientRect().height > 100), null, { timeout: 20_000 });
    const s = await shown(page);
    check(
      '… a first visit in Chinese shows the Chinese drawings, the side section’s labels in Chinese',
      s.first && s.zh && s.drawings.length === 3 && s.drawings.every((d) => d.lang === 'zh') && s.drawings[0].text.includes('大径 Ø48') && s.code.length === 1,
      JSON.stringify(s.drawings.map((d) => [d.lang, d.text.slice(0, 40)])),
    );
    const zh = await words(page);
    await page.screenshot({ path: path.join(shots, 'first-static-zh.png') });
    release();
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60_000 });
    const after = await shown(page);
    const lang = await page.evaluate(() => document.documentElement.lang);
    check('… which the app, speaking Chinese, replaces', !after.first && !after.zh && after.parts === 0 && lang === 'zh-CN', `${lang} ${JSON.stringify(after)}`);
    const zhApp = await words(page);
    check(
      '… the page’s own words before the app’s script (texts, titles, placeholders, the title, the language) were the app’s Chinese ones',
      zh.named.length >= 25 && zh.named.some(([, k, text]) => k === 'passes' && text === '走刀') && zh.named.some(([, k, text]) => k === 'new' && text === '新建') && differ(zh, zhApp).length === 0,
      differ(zh, zhApp).join(' | '),
    );
    await close();
  }
  check('no page errors', problems.length === 0, problems.join(' | '));
} catch (e) {
  check('the first-visit test ran to the end', false, e.stack || String(e));
}
clearTimeout(timer);
finish('first visit', counts);
