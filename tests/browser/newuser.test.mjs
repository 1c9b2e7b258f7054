// Browser test: what a new user hits (the issue of the same name).
// node newuser.test.mjs http://127.0.0.1:PORT/
//
// 1. A pass on another helix (O1006 with one pass at F2.5) is a
//    cross-thread warning on that pass's line.
// 2. O1006 named M48x2-6g gauges with the tool not known (a full-profile
//    insert taken, and said), and the change is named ΔX.
// 3. A new program does not show the last one's designation, nor keep its
//    chosen start; a failed export says why.
// 4. The greyed drawing under an alarm is the plan the user left, not a
//    keystroke on the way; the alarm banner does not cover the drawing.
// 5. LinuxCNC code under Fanuc gets a dialect hint whose button switches
//    the controller; "New" says which controller it is for; the examples
//    have one per controller.
// 6. The wizard's program plans to the crest it states.
// 7. Open…, Save, Print, find (Ctrl-F), Help, a hint in an empty program.
// Screenshots (1440×900 and 390 wide, English and Chinese) go to
// tests/browser/screenshots/newuser-*.png.

import { siteUrl, checker, guard, openApp, finish, shots } from './harness.mjs';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const url = siteUrl('newuser.test.mjs');
const { check, counts } = checker();
const timer = guard(240, 'the new-user test');
const problems = [];
const { page, close } = await openApp('screwcut-newuser-', url, { width: 1440, height: 900 }, problems);

const O1006 = fs.readFileSync(new URL('../../examples/o1006.nc', import.meta.url), 'utf8');
const rows = () => page.locator('#passes tbody tr[data-pass]').count();
const diags = () => page.locator('#diagnostics li').allTextContents();
const setText = (text) => page.evaluate((text) => window.__screwcut.editor().setText(text), text);
const settle = () => page.waitForTimeout(400);
/** Opens `text` as a new program for `dialect` through the app's own list. */
const openNew = (text, dialect) => page.evaluate(([text, dialect]) => window.__screwcut.library.openNew({ dialect, settings: {}, program: text }), [text, dialect]);

try {
  // ---- 1. another helix ----
  await openNew(O1006.replace('N120 G32 Z13.0 F2.0;', 'N120 G32 Z13.0 F2.5;'), 'gsk980tdc');
  await page.waitForFunction(() => [...document.querySelectorAll('#diagnostics li')].some((li) => li.textContent.includes('cross-thread')), null, { timeout: 10_000 }).catch(() => {});
  const cross = (await diags()).find((d) => d.includes('cross-thread')) || '';
  check('1. a pass at F2.5 among F2 passes: cross-thread on its line 14', cross.startsWith('14:') && cross.includes('lead of 2.5'), cross);

  // ---- 2. the gauge with the tool not known ----
  await openNew(O1006.replace('O1006;', 'O1006; (M48x2-6g)'), 'gsk980tdc');
  await page.waitForFunction(() => document.querySelector('#check-verdict .verdict'), null, { timeout: 10_000 }).catch(() => {});
  const verdict = await page.locator('#check-verdict').textContent();
  check('2. O1006 M48x2-6g gauges with the tool not known', verdict.includes('gauges') && !verdict.includes('fails'), verdict);
  check('… the full-profile radius is shown as assumed, the change named ΔX', verdict.includes('r 0.25 assumed') && verdict.includes('ΔX'), verdict);
  const falseFail = (await diags()).filter((d) => d.includes('gauge-fail'));
  check('… and no gauge-fail', falseFail.length === 0, JSON.stringify(falseFail));
  await page.screenshot({ path: path.join(shots, 'newuser-gauge-en-1440.png') });

  // ---- 3. state of one program not carried to the next ----
  await page.fill('#designation', 'M48x2-4h');
  await page.waitForTimeout(600);
  await page.click('#program-new');
  await settle();
  const designation = await page.locator('#designation').inputValue();
  const placeholder = await page.locator('#designation').getAttribute('placeholder');
  check('3. New: the designation typed for the last program is not shown', designation === '', designation);
  check('… and its placeholder reads as an example', placeholder.startsWith('e.g.'), placeholder);
  const newNote = await page.locator('#notices .notice').allTextContents();
  check('… New says which controller the program is for', newNote.some((n) => n.includes('new program for GSK980TDc')), JSON.stringify(newNote));
  const hint = await page.evaluate(() => document.querySelector('.cm-placeholder')?.textContent || '');
  check('… an empty program says what to do', hint.includes('Type or paste G-code') && hint.includes('Open…'), hint);
  // A two-start program, start 2 chosen; then another program with one start: its tooth exports.
  await openNew(fs.readFileSync(new URL('../../examples/g32-multistart-q.nc', import.meta.url), 'utf8'), 'gsk980tdc');
  await page.waitForFunction(() => !document.getElementById('start-pick').hidden, null, { timeout: 10_000 }).catch(() => {});
  await page.selectOption('#start', '2');
  await settle();
  await openNew(O1006, 'gsk980tdc');
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
  check('… the start chosen in the last program is not kept: five passes listed', (await rows()) === 5, String(await rows()));
  const download = page.waitForEvent('download', { timeout: 10_000 }).catch(() => null);
  await page.click('#tooth-panel [data-act="svg"]');
  const svg = await download;
  check('… and its tooth view exports', !!svg && svg.suggestedFilename() === 'screwcut-tooth.svg', svg ? svg.suggestedFilename() : 'no download');
  await openNew('G00 X40 Z5\nG01 X30 F0.2\nM30\n', 'gsk980tdc');
  await settle();
  await page.click('#tooth-panel [data-act="svg"]');
  await page.waitForFunction(() => (document.getElementById('toast').textContent || '').length > 0, null, { timeout: 5_000 }).catch(() => {});
  const toast = await page.locator('#toast').textContent();
  check('… a program with no thread: the tooth export says why', toast.includes('Tooth section was not exported') && toast.includes('no thread'), toast);

  // ---- 4. the greyed drawing is the plan the user left ----
  await openNew(O1006, 'gsk980tdc');
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
  await page.waitForTimeout(1200);
  // Type an extra block quickly, through a momentarily valid prefix (X2), to an alarm (X2#2.6).
  await page.locator('.cm-line', { hasText: 'N200 G32' }).click();
  await page.keyboard.press('End');
  await page.keyboard.type('\nX2');
  await page.waitForTimeout(150);
  await page.keyboard.type('#2.6');
  await page.waitForFunction(() => !document.getElementById('stale').hidden, null, { timeout: 10_000 }).catch(() => {});
  const threads = await page.locator('#thread option').count();
  check('4. under the alarm the greyed plan is the one left (O1006: one thread, five passes)', threads === 1 && (await rows()) === 5, `${threads} threads, ${await rows()} rows`);
  const header = await page.evaluate(() => {
    const h = document.querySelector('header');
    const first = h.firstElementChild.getBoundingClientRect();
    return [...h.children].filter((c) => c.offsetParent !== null).every((c) => Math.abs(c.getBoundingClientRect().top - first.top) < first.height);
  });
  check('8. at 1440×900 the header is one row', header, '');
  const firstTab = await page.evaluate(() => {
    document.activeElement?.blur();
    return [...document.querySelectorAll('a[href], button, select, input')].find((e) => e.offsetParent !== null || e.classList.contains('skip'))?.className;
  });
  check('… a skip link comes first', firstTab === 'skip', String(firstTab));
  const tableRows = await page.evaluate(() => {
    const s = document.querySelector('.row.lists .scroll');
    return Math.floor((s.clientHeight - 30) / 22);
  });
  check('… the pass table shows at least 7 rows', tableRows >= 7, String(tableRows));
  const layout = await page.evaluate(() => {
    const b = document.getElementById('stale').getBoundingClientRect();
    const c = document.getElementById('side').getBoundingClientRect();
    return { banner: [b.top, b.bottom], canvas: [c.top, c.bottom] };
  });
  check('… the alarm banner is above the drawing, not over it', layout.banner[1] <= layout.canvas[0] + 0.5, JSON.stringify(layout));
  await page.screenshot({ path: path.join(shots, 'newuser-stale-en-1440.png') });

  // ---- 5. the controller ----
  await openNew('G18 G21 G90\nM3 S500\nG0 X30 Z5\nG76 P2 Z-30 I-1 J0.3 K1.23\nM2\n', 'fanuc0i');
  await page.waitForFunction(() => document.querySelector('#diagnostics button.switch'), null, { timeout: 10_000 }).catch(() => {});
  const sw = page.locator('#diagnostics button.switch');
  check('5. LinuxCNC code under Fanuc: a dialect hint with a switch', (await sw.count()) === 1 && (await sw.textContent()) === 'Read it as LinuxCNC', String(await sw.count()));
  await page.locator('#diagnostics li', { hasText: 'dialect-hint' }).first().screenshot({ path: path.join(shots, 'newuser-hint-en.png') });
  await sw.click();
  await page.waitForFunction(() => document.getElementById('dialect').value === 'linuxcnc', null, { timeout: 5_000 }).catch(() => {});
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length > 0, null, { timeout: 10_000 }).catch(() => {});
  check('… one click reads it as LinuxCNC: no alarm, passes listed', (await page.locator('#dialect').inputValue()) === 'linuxcnc' && (await rows()) > 0 && !(await diags()).some((d) => d.includes('alarm')), JSON.stringify(await diags()));
  const examples = await page.evaluate(() => JSON.parse(document.getElementById('examples').dataset.list || '[]').map((e) => e.dialect));
  check('… the examples have one for each controller', ['gsk980tdc', 'fanuc0i', 'renhe', 'linuxcnc'].every((d) => examples.includes(d)), JSON.stringify(examples));

  // ---- 6. the wizard states the crest the preview uses ----
  await page.click('#wizard');
  const dlg = page.locator('dialog.wizard');
  await dlg.waitFor({ timeout: 10_000 });
  await dlg.locator('input[name="designation"]').fill('M20x1.5-6g');
  await dlg.locator('input[name="length"]').fill('20');
  await dlg.locator('select[name="dialect"]').selectOption('gsk980tdc');
  await dlg.locator('select[name="form"]').selectOption('g32');
  await page.waitForFunction(() => (document.querySelector('dialog.wizard .wz-program')?.textContent || '').includes('crest X'), null, { timeout: 10_000 }).catch(() => {});
  const written = await dlg.locator('.wz-program').textContent();
  const crest = (written.match(/\(crest X([\d.]+)/) || [])[1];
  await dlg.locator('button[value="open"]').click();
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length > 0, null, { timeout: 10_000 }).catch(() => {});
  const assumed = (await diags()).some((d) => d.includes('crest-assumed'));
  const overDigits = /X\d+\.\d{4}/.test(written.split('\n').filter((l) => !l.startsWith('(')).join('\n'));
  check('6. the wizard states its crest in a comment the preview reads', !!crest && !assumed, `${crest} ${assumed}`);
  check('… and writes no X finer than 0.001 mm', !overDigits, written.slice(0, 400));

  // ---- 7. in and out ----
  const file = path.join(os.tmpdir(), `screwcut-open-${process.pid}.ngc`);
  fs.writeFileSync(file, '(OPENED FROM A FILE)\r\nG18 G21 G90 G7\r\nM3 S500\r\nG0 X22 Z3\r\nG76 P1.5 Z-20 I-2 J0.3 K2\r\nM2\r\n');
  const chooser = page.waitForEvent('filechooser', { timeout: 5_000 });
  await page.click('#file-menu summary');
  await page.click('#file-open');
  await (await chooser).setFiles(file);
  await page.waitForFunction(() => (window.__screwcut.text() || '').includes('OPENED FROM A FILE'), null, { timeout: 10_000 }).catch(() => {});
  const opened = await page.evaluate(() => ({ text: window.__screwcut.text(), dialect: document.getElementById('dialect').value }));
  check('7. Open… reads a .ngc file as a new LinuxCNC program (CR LF made LF)', opened.dialect === 'linuxcnc' && opened.text.startsWith('(OPENED FROM A FILE)\nG18') && !opened.text.includes('\r'), JSON.stringify(opened).slice(0, 200));
  fs.rmSync(file, { force: true });
  const saved = page.waitForEvent('download', { timeout: 10_000 }).catch(() => null);
  await page.click('#file-menu summary');
  await page.click('#file-save');
  const s = await saved;
  const savedText = s ? fs.readFileSync(await s.path(), 'utf8') : '';
  check('… Save writes it back as OPENED_FROM_A_FILE.ngc', !!s && s.suggestedFilename() === 'OPENED_FROM_A_FILE.ngc' && savedText === opened.text, s ? s.suggestedFilename() : 'no download');
  await page.locator('.cm-content').click();
  await page.keyboard.press('Control+f');
  const panel = await page.waitForSelector('.cm-search', { timeout: 5_000 }).catch(() => null);
  check('… Ctrl-F opens find and replace', !!panel, '');
  await page.keyboard.press('Escape');
  check('… a Help link to the documentation page', (await page.getAttribute('#help', 'href')) === 'docs.html', '');
  await page.emulateMedia({ media: 'print' });
  await page.evaluate(() => window.dispatchEvent(new Event('beforeprint')));
  const sheet = await page.evaluate(() => ({ shown: getComputedStyle(document.getElementById('print-sheet')).display, text: document.getElementById('print-sheet').textContent }));
  check('… Print lays out the whole program and every pass', sheet.shown === 'block' && sheet.text.includes('OPENED FROM A FILE') && sheet.text.includes('Passes of thread 1'), JSON.stringify(sheet).slice(0, 300));
  await page.pdf({ path: path.join(shots, 'newuser-print-en.pdf'), format: 'A4' }).catch(() => {});
  await page.screenshot({ path: path.join(shots, 'newuser-print-en.png'), fullPage: true });
  await page.emulateMedia({ media: 'screen' });

  // ---- the insert, a text setting in the Parameters panel ----
  await openNew(O1006, 'gsk980tdc');
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 10_000 }).catch(() => {});
  await page.click('#settings-toggle');
  const insert = page.locator('#settings-form input[data-name="tool.insert"]');
  await insert.fill('16ER 1.5 ISO');
  await insert.dispatchEvent('change');
  await page.waitForFunction(() => [...document.querySelectorAll('#diagnostics li')].some((li) => li.textContent.includes('insert-pitch')), null, { timeout: 10_000 }).catch(() => {});
  const ins = (await diags()).find((d) => d.includes('insert-pitch')) || '';
  check('the insert typed in Parameters: a 1.5 mm insert on O1006 (pitch 2) is warned about', ins.includes('made for a pitch of 1.5 mm'), ins);
  await insert.fill('');
  await insert.dispatchEvent('change');
  await page.click('#settings-toggle');

  // ---- Chinese, and a phone ----
  await page.click('#lang');
  await openNew(O1006.replace('O1006;', 'O1006; (M48x2-6g)'), 'gsk980tdc');
  await page.waitForFunction(() => document.querySelector('#check-verdict .verdict'), null, { timeout: 10_000 }).catch(() => {});
  const zh = await page.locator('#check-verdict').textContent();
  check('in Chinese: the verdict and the assumed tool', zh.includes('合格') && zh.includes('按全牙型刀片假定') && zh.includes('ΔX'), zh);
  await page.screenshot({ path: path.join(shots, 'newuser-gauge-zh-1440.png') });
  // The Parameters panel in Chinese: no choice is cut short.
  await page.click('#settings-toggle');
  const cut = await page.evaluate(() =>
    [...document.querySelectorAll('#settings-form select')]
      .filter((s) => {
        // The chosen entry's text in the select's own font, plus room for its arrow.
        const probe = document.createElement('span');
        probe.style.cssText = 'position:absolute;visibility:hidden;white-space:nowrap';
        probe.style.font = getComputedStyle(s).font;
        probe.textContent = s.selectedOptions[0]?.textContent || '';
        document.body.appendChild(probe);
        const w = probe.getBoundingClientRect().width;
        probe.remove();
        return w + 16 > s.getBoundingClientRect().width;
      })
      .map((s) => s.dataset.name),
  );
  check('8. in Chinese no parameter choice is cut short', cut.length === 0, JSON.stringify(cut));
  await page.locator('#settings').screenshot({ path: path.join(shots, 'newuser-settings-zh.png') });
  await page.click('#settings-toggle');
  await page.setViewportSize({ width: 390, height: 844 });
  await settle();
  await page.screenshot({ path: path.join(shots, 'newuser-zh-390.png'), fullPage: true });
  await page.click('#lang');
  await settle();
  await page.screenshot({ path: path.join(shots, 'newuser-en-390.png'), fullPage: true });
  check('no console or page errors', problems.length === 0, JSON.stringify(problems));
} catch (e) {
  check('the new-user test ran to the end', false, e && e.stack ? e.stack : String(e));
} finally {
  clearTimeout(timer);
  await close();
}
finish('newuser', counts);
