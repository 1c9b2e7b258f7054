// Programs in and out of the page: Open… (a file as a new program), Save
// (the program as a file) and Print (the drawings as shown, then the whole
// program, every pass of the chosen thread and every diagnostic, on A4).
// The editor shows only the lines in view and the pass table only the rows
// in view, so printing lays the program and the lists out in full in
// #print-sheet first.

import { diagnosticRow, passHead, passRow } from '../shared/lists.js';
import { esc } from '../shared/table.js';
import { programName } from './store.js';

/** Largest file Open… reads (the planner's own limit is a setting; this keeps a tab alive). */
const MAX_MB = 20;

/** A file name for the program `text` of `dialect`: its name (O number, comment), safe characters only. */
export function fileName(text, dialect) {
  const base =
    programName(text)
      .replace(/[^\w.-]+/g, '_')
      .replace(/^_+|_+$/g, '')
      .slice(0, 60) || 'program';
  return `${base}.${dialect === 'linuxcnc' ? 'ngc' : 'nc'}`;
}

/**
 * Reads `file` and calls `open({dialect, program, name})` with it (a `.ngc`
 * file is LinuxCNC's); a file too large or unreadable is a message, not an error.
 */
export async function openFile(file, { dialect, open, say, t }) {
  if (!file) return;
  const mb = file.size / 1048576;
  if (mb > MAX_MB) {
    say(t('file_too_big', { name: file.name, size: mb.toFixed(1), max: MAX_MB }));
    return;
  }
  let text;
  try {
    text = await file.text();
  } catch (e) {
    say(t('file_unreadable', { name: file.name, why: String((e && e.message) || e) }));
    return;
  }
  const ext = (file.name.split('.').pop() || '').toLowerCase();
  await open({ dialect: ext === 'ngc' ? 'linuxcnc' : dialect, program: text.replace(/\r\n?/g, '\n') });
  say(t('opened_file', { name: file.name }));
}

/**
 * Fills `sheet` for printing: the program with its line numbers, the pass
 * table of the chosen thread in full (`result.passes`, columns) and the
 * diagnostics.
 */
export function fillPrintSheet(sheet, { text, result, thread, t }) {
  const lines = text.split('\n');
  const width = String(lines.length).length;
  const program = lines.map((l, i) => `${String(i + 1).padStart(width)}  ${l}`).join('\n');
  let html = `<h2>${esc(t('print_program'))}</h2><pre>${esc(program)}</pre>`;
  const c = result && result.passes;
  const th = result && result.threads[thread];
  if (c && th) {
    const rows = Array.from({ length: c.n }, (_, i) => passRow(c, i, t, false, false)).join('');
    html += `<h2>${esc(t('print_passes', { n: thread + 1 }))}</h2><table><thead>${passHead(t, th.units || result.units)}</thead><tbody>${rows}</tbody></table>`;
  }
  const diags = (result && result.diagnostics) || [];
  if (diags.length) html += `<h2>${esc(t('print_diagnostics'))}</h2><ul>${diags.map((d, i) => diagnosticRow(d, i, t, false)).join('')}</ul>`;
  sheet.innerHTML = html;
}
