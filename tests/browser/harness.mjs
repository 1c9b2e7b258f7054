// Shared by the browser tests: the site's URL from the command line,
// pass/fail counting, the screenshot folder, a time guard, and the system
// Chromium (/usr/bin/chromium) started with the flags this machine needs.
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { execFileSync } from 'node:child_process';

/** The system Chromium the tests drive. */
export const CHROMIUM = '/usr/bin/chromium';

/** Headless Chromium as root, without the network it must not reach. */
export const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

/** The site's URL, the first argument; usage and exit 2 without it. */
export function siteUrl(script) {
  const url = process.argv[2];
  if (!url) {
    console.error(`usage: node ${script} http://127.0.0.1:PORT/`);
    process.exit(2);
  }
  return url;
}

/** tests/browser/screenshots/, created. */
export const shots = path.join(path.dirname(fileURLToPath(import.meta.url)), 'screenshots');
fs.mkdirSync(shots, { recursive: true });

/** A check function that prints each result, and the counts it keeps. */
export function checker() {
  const counts = { passed: 0, failed: 0 };
  const check = (name, ok, detail = '') => {
    if (ok) {
      counts.passed++;
      console.log(`ok   ${name}`);
    } else {
      counts.failed++;
      console.log(`FAIL ${name}${detail ? `: ${detail}` : ''}`);
    }
  };
  return { check, counts };
}

/** Fails the test (exit 1) if it runs longer than `seconds`. */
export function guard(seconds, what) {
  return setTimeout(() => {
    console.log(`FAIL ${what} took longer than ${seconds} s`);
    process.exit(1);
  }, seconds * 1000);
}

/** What `chromium --version` prints, for the test log. */
export function chromiumVersion() {
  try {
    return execFileSync(CHROMIUM, ['--version'], { encoding: 'utf8', timeout: 20_000, stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch (e) {
    return `unknown (${CHROMIUM} --version failed: ${e.message.split('\n')[0]})`;
  }
}

/**
 * A persistent Chromium context in a fresh profile; `close()` removes the
 * profile. Prints the browser's version first, so a log says
 * which Chromium a result came from.
 */
export async function launch(prefix, options = {}) {
  console.log(`browser: ${chromiumVersion()}`);
  const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), prefix));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: CHROMIUM,
    headless: true,
    args: CHROMIUM_ARGS,
    ...options,
  });
  const close = async () => {
    await context.close();
    fs.rmSync(userDataDir, { recursive: true, force: true });
  };
  return { context, close };
}

/** Prints the summary line and exits 1 when a check failed. */
export function finish(label, counts) {
  console.log(`${label}: ${counts.passed} passed, ${counts.failed} failed`);
  process.exit(counts.failed ? 1 : 0);
}

/**
 * Opens the app at `url` in a launched browser (`prefix` names its profile)
 * with O1006 planned (its five passes in the table); page errors and console
 * errors go to `problems`. Returns `{page, close}`.
 */
export async function openApp(prefix, url, viewport, problems, onContext = () => {}) {
  const { context, close } = await launch(prefix, { viewport });
  onContext(context);
  const page = context.pages()[0] || (await context.newPage());
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.waitForFunction(() => document.querySelectorAll('#passes tbody tr[data-pass]').length === 5, null, { timeout: 30_000 });
  return { page, close };
}
