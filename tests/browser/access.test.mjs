// Browser test: the app by keyboard, on a phone, and in Chinese.
// node access.test.mjs http://127.0.0.1:PORT/
//
// - Every drawing is a focusable image with a label that says what it
//   shows in numbers (O1006: 5 passes from X47.1 to X45.4, Z70 to Z13) and
//   moves by keyboard (an arrow key pans the view).
// - The pass table and the diagnostics list are one tab stop each: arrow
//   keys choose a row (its lines marked in the program, the row read out),
//   Enter goes to its line.
// - At 390×844 (a phone) the page is no wider than the screen and every
//   header control is on it; the Parameters panel opens over the page and
//   closes.
// - In Chinese, the page's own words are Chinese; screenshots in both
//   languages at 1440×900 and 390×844 go to tests/browser/screenshots/.

import { siteUrl, checker, guard, openApp, finish, shots } from './harness.mjs';
import path from 'node:path';

const url = siteUrl('access.test.mjs');
const { check, counts } = checker();
const timer = guard(120, 'the access test');
const problems = [];

async function open(viewport) {
  const opened = await openApp('screwcut-access-', url, viewport, problems);
  await opened.page.waitForTimeout(400);
  return opened;
}

try {
  // ---- keyboard, 1440×900 ----
  {
    const { page, close } = await open({ width: 1440, height: 900 });
    for (const id of ['side', 'tooth', 'starts']) {
      const a = await page.evaluate((id) => {
        const c = document.getElementById(id);
        return { role: c.getAttribute('role'), label: c.getAttribute('aria-label') || '', tab: c.tabIndex };
      }, id);
      check(`the ${id} view is a focusable image with a label`, a.role === 'img' && a.tab === 0 && a.label.length > 30, JSON.stringify(a));
    }
    const side = await page.getAttribute('#side', 'aria-label');
    check('the side view says what it shows, in numbers', side.includes('5 passes from X47.1 to X45.4, Z70 to Z13') && side.includes('lead 2'), side);
    const before = await page.evaluate(() => window.__screwcut.inspect('view', 'side').then((v) => v.transform.tx));
    await page.focus('#side');
    await page.keyboard.press('ArrowLeft');
    await page.waitForTimeout(200);
    const after = await page.evaluate(() => window.__screwcut.inspect('view', 'side').then((v) => v.transform.tx));
    check('an arrow key pans the focused drawing', after !== before, `${before} → ${after}`);

    const table = page.locator('#passes').locator('xpath=..');
    check('the pass table is one tab stop with a name', (await table.getAttribute('tabindex')) === '0' && ((await table.getAttribute('aria-label')) || '').length > 10);
    await table.focus();
    await page.keyboard.press('ArrowDown');
    await page.keyboard.press('ArrowDown');
    await page.waitForTimeout(300);
    const hot = await page.locator('#passes tr.hot td:first-child').textContent().catch(() => '');
    check('arrow keys choose pass 2', hot === '2', hot);
    const read = await page.textContent('#a11y-live');
    check('… which is read out', read.startsWith('Pass 2') && read.includes('X46.5'), read);
    const marked = await page.$$eval('.cm-line.cm-marked', (l) => l.map((x) => x.textContent));
    check('… and its four lines are marked in the program', marked.length === 4 && marked[0].includes('X46.5'), JSON.stringify(marked));
    await page.keyboard.press('Enter');
    await page.waitForTimeout(200);
    const line = await page.evaluate(() => window.__screwcut.editor().cursorLine());
    check('Enter goes to its first line (9)', line === 9, String(line));

    const diags = page.locator('#diagnostics').locator('xpath=..');
    await diags.focus();
    await page.keyboard.press('ArrowDown');
    await page.waitForTimeout(200);
    const d = await page.textContent('#a11y-live');
    check('the diagnostics list is operated the same way', (await page.locator('#diagnostics li.hot').count()) === 1 && d.startsWith('5:1'), d);
    await page.keyboard.press('Enter');
    await page.waitForTimeout(200);
    check('… Enter goes to the diagnostic’s line', (await page.evaluate(() => window.__screwcut.editor().cursorLine())) === 5);
    check('the examples menu has a name', ((await page.getAttribute('#examples', 'aria-label')) || '').length > 5);
    await page.screenshot({ path: path.join(shots, 'access-en-1440.png') });
    // Another program with an alarm shows no greyed drawing of the one before.
    await page.click('#program-new');
    await page.waitForTimeout(500);
    await page.locator('.cm-content').click();
    // In one piece: typed key by key, a half-typed F1.2 plans without an alarm and is rightly kept greyed.
    await page.keyboard.insertText('G00 X40 Z5\nG32 Z-20 F1.2.3\n');
    await page.waitForSelector('#diagnostics li.error', { timeout: 10_000 }).catch(() => {});
    await page.waitForTimeout(300);
    const stale = await page.evaluate(() => ({ banner: !document.getElementById('stale').hidden, table: document.getElementById('passes').classList.contains('stale') }));
    check('a new program with an alarm shows no greyed drawing or table of the program before', !stale.banner && !stale.table, JSON.stringify(stale));
    await page.selectOption('#programs', { index: 1 });
    await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
    await page.click('#lang');
    await page.waitForTimeout(600);
    const zh = await page.evaluate(() => ({ head: document.querySelector('#passes thead').textContent, label: document.getElementById('side').getAttribute('aria-label'), summary: document.getElementById('summary').textContent, timing: document.getElementById('timing').textContent }));
    check('in Chinese the table, the drawing’s label, the summary and its timing are Chinese', zh.head.includes('切深') && zh.label.includes('条螺纹') && zh.summary.includes('条螺纹') && zh.timing.startsWith('计算 '), JSON.stringify(zh));
    // A message shown before the switch (the new program's, in English) follows it: its text and its close button's name.
    const notice = await page.evaluate(() => [...document.querySelectorAll('#notices .notice')].map((n) => [n.querySelector('.text').textContent, n.querySelector('.close').getAttribute('aria-label')]));
    check('… and so does the message shown in English before the switch', notice.length === 1 && notice[0][0].startsWith('已为 GSK980TDc 新建程序') && /[\u4e00-\u9fff]/.test(notice[0][1]), JSON.stringify(notice));
    // The diagnostics, the editor's lint and the thread's kind follow the language.
    const words = () =>
      page.evaluate(() => ({
        diag: document.querySelector('#diagnostics li')?.textContent || '',
        kind: document.querySelector('#thread option')?.textContent || '',
        lint: (window.__screwcut.result?.diagnostics || [])[0]?.message || '',
      }));
    const zhWords = await words();
    check(
      'in Chinese the first diagnostic and the thread’s kind are Chinese',
      zhWords.diag.includes('提示') && zhWords.diag.includes('程序没有车出这个螺纹的大径') && zhWords.kind.includes('G32 直螺纹') && zhWords.lint.startsWith('程序没有'),
      JSON.stringify(zhWords),
    );
    await page.screenshot({ path: path.join(shots, 'access-zh-1440.png') });
    await page.click('#lang');
    await page.waitForTimeout(600);
    const enWords = await words();
    check(
      '… and English again after switching back',
      enWords.diag.includes('the program does not turn this thread’s major diameter'.replace('’', "'")) && enWords.kind.includes('G32 straight') && enWords.lint.startsWith('the program'),
      JSON.stringify(enWords),
    );
    await close();
  }

  // ---- a phone, 390×844 ----
  {
    const { page, close } = await open({ width: 390, height: 844 });
    const m = await page.evaluate(() => ({
      width: document.documentElement.scrollWidth,
      off: [...document.querySelectorAll('header button, header select')]
        .filter((e) => e.offsetParent)
        .map((e) => [e.id, e.getBoundingClientRect()])
        .filter(([, r]) => r.left < 0 || r.right > window.innerWidth)
        .map(([id]) => id),
    }));
    check('at 390 px the page is no wider than the screen', m.width <= 390, String(m.width));
    check('… and every header control is on it', m.off.length === 0, JSON.stringify(m.off));
    const views = await page.evaluate(() => ['side', 'tooth', 'starts'].map((id) => Math.round(document.getElementById(id).getBoundingClientRect().width)));
    check('… the drawings take the screen’s width', views.every((w) => w >= 360 && w <= 390), JSON.stringify(views));
    const ink = await page.evaluate(() => window.__screwcut.inspect('pixels', 'side'));
    check('… and are drawn', ink.n > 300, JSON.stringify(ink));
    await page.screenshot({ path: path.join(shots, 'access-en-390.png'), fullPage: true });
    await page.click('#settings-toggle');
    const panel = await page.evaluate(() => {
      const r = document.getElementById('settings').getBoundingClientRect();
      return { left: r.left, right: r.right, w: window.innerWidth };
    });
    check('the Parameters panel opens over the page, full width', panel.left === 0 && panel.right === panel.w, JSON.stringify(panel));
    await page.click('#settings-close');
    check('… and closes', await page.locator('#settings').isHidden());
    await page.click('#lang');
    await page.waitForTimeout(600);
    check('in Chinese too the page fits', (await page.evaluate(() => document.documentElement.scrollWidth)) <= 390);
    await page.screenshot({ path: path.join(shots, 'access-zh-390.png'), fullPage: true });
    await close();
  }
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check(`the test ran to its end (${e.message})`, false);
}
clearTimeout(timer);
finish('access', counts);
