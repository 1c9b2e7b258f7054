// The plan's diagnostics in the code pane: an underline by severity, a
// marker in a gutter on each line that has one (its messages as the
// marker's title), the messages of the text under the pointer, and F8 /
// Shift-F8 to go to the next / previous one.
//
// The ranges are kept as CodeMirror range sets mapped through each edit, so
// a keystroke costs the same whatever the number of diagnostics; a new list
// is one pass over it. (`@codemirror/lint`, used before, also kept a
// selected diagnostic that each keystroke looked up again and rebuilt
// every gutter marker with each list: the page alone then painted a
// keystroke at 1.2–1.6× the bare editor in a 5,000-line program with 601
// diagnostics, against 1.05–1.2× with these sets; docs/performance.md.)

import { RangeSet, RangeSetBuilder, StateEffect, StateField } from '@codemirror/state';
import { Decoration, EditorView, GutterMarker, gutter, hoverTooltip, keymap, WidgetType } from '@codemirror/view';

const RANK = { info: 0, warning: 1, error: 2 };
const SEVERITY = ['info', 'warning', 'error'];

/** Replaces the diagnostics shown with the list given (`{from, to, severity, message, code}`, UTF-16 offsets). */
const setList = StateEffect.define();

/** A diagnostic at a point (an empty range): a small mark where it is. */
class PointWidget extends WidgetType {
  constructor(severity) {
    super();
    this.severity = severity;
  }
  eq(o) {
    return o.severity === this.severity;
  }
  toDOM() {
    const s = document.createElement('span');
    s.className = `cm-diag-point cm-diag-point-${this.severity}`;
    return s;
  }
}

/** A gutter marker: the line's worst severity, its messages as the title. */
class LineMarker extends GutterMarker {
  constructor(severity, title) {
    super();
    this.severity = severity;
    this.title = title;
  }
  eq(o) {
    return o.severity === this.severity && o.title === this.title;
  }
  toDOM() {
    const d = document.createElement('div');
    d.className = `cm-diag-marker cm-diag-marker-${this.severity}`;
    d.title = this.title;
    return d;
  }
}

/** One line of a message as shown: the text, how many times it was raised (×50, when more than once) and its code. */
const said = (d) => `${d.message}${d.repeats > 1 ? ` ×${d.repeats}` : ''}${d.code ? ` (${d.code})` : ''}`;

/** The worst severity of `list`. */
const worst = (list) => SEVERITY[Math.max(...list.map((d) => RANK[d.severity] ?? 0))];

/** The marks and gutter markers of `list` in `doc`: diagnostics of one range share a mark; those of one line a marker. */
function build(list, doc) {
  const len = doc.length;
  const clamped = list.map((d) => {
    const from = Math.min(Math.max(d.from, 0), len);
    return { ...d, from, to: Math.min(Math.max(d.to, from), len), severity: RANK[d.severity] === undefined ? 'info' : d.severity };
  });
  clamped.sort((a, b) => a.from - b.from || a.to - b.to);
  const marks = new RangeSetBuilder();
  const lines = new RangeSetBuilder();
  let line = null;
  let onLine = [];
  const endLine = () => {
    if (line) lines.add(line.from, line.from, new LineMarker(worst(onLine), onLine.map(said).join('\n')));
  };
  for (let i = 0; i < clamped.length; ) {
    const { from, to } = clamped[i];
    let j = i + 1;
    while (j < clamped.length && clamped[j].from === from && clamped[j].to === to) j++;
    const same = clamped.slice(i, j);
    const severity = worst(same);
    if (from < to) marks.add(from, to, Decoration.mark({ class: `cm-diag cm-diag-${severity}`, diagnostics: same }));
    else marks.add(from, from, Decoration.widget({ widget: new PointWidget(severity), side: 1, diagnostics: same }));
    if (!line || from > line.to) {
      endLine();
      line = doc.lineAt(from);
      onLine = [];
    }
    onLine.push(...same);
    i = j;
  }
  endLine();
  return { marks: marks.finish(), lines: lines.finish() };
}

const field = StateField.define({
  create: () => ({ marks: Decoration.none, lines: RangeSet.empty }),
  update(value, tr) {
    for (const e of tr.effects) if (e.is(setList)) return build(e.value, tr.state.doc);
    if (!tr.docChanged) return value;
    return { marks: value.marks.map(tr.changes), lines: value.lines.map(tr.changes) };
  },
  provide: (f) => EditorView.decorations.from(f, (v) => v.marks),
});

/** The diagnostics whose range holds `pos` (a point's at `pos`), with the span they cover. */
function at(state, pos) {
  const found = [];
  let from = pos;
  let to = pos;
  // The ranges that touch `pos`: those that start at or before it and end at or after it.
  state.field(field).marks.between(pos, pos, (a, b, deco) => {
    found.push(...deco.spec.diagnostics);
    from = Math.min(from, a);
    to = Math.max(to, b);
  });
  return { found, from, to };
}

/** The messages under the pointer, in a tooltip. */
const tooltip = hoverTooltip((view, pos) => {
  const { found, from, to } = at(view.state, pos);
  if (!found.length) return null;
  return {
    pos: from,
    end: to,
    above: true,
    create() {
      const dom = document.createElement('ul');
      dom.className = 'cm-diag-tip';
      for (const d of found) {
        const li = document.createElement('li');
        li.className = `cm-diag-tip-${d.severity}`;
        li.textContent = said(d);
        dom.append(li);
      }
      return { dom };
    },
  };
});

/** Moves the cursor to the start of the next (`dir` 1) or previous (−1) diagnostic, round the end; false when there is none. */
function go(dir) {
  return (view) => {
    const { marks } = view.state.field(field);
    const head = view.state.selection.main.head;
    let first = -1;
    let last = -1;
    let next = -1;
    let prev = -1;
    marks.between(0, view.state.doc.length, (from) => {
      if (first < 0) first = from;
      last = from;
      if (from > head && next < 0) next = from;
      if (from < head) prev = from;
    });
    const to = dir > 0 ? (next >= 0 ? next : first) : prev >= 0 ? prev : last;
    if (to < 0) return false;
    view.dispatch({ selection: { anchor: to }, scrollIntoView: true });
    return true;
  };
}

const theme = EditorView.baseTheme({
  // Thin and close under the text, so that the wave stays within its own line.
  '.cm-diag': { textDecorationLine: 'underline', textDecorationStyle: 'wavy', textDecorationSkipInk: 'none', textDecorationThickness: '1px', textUnderlineOffset: '1px' },
  '.cm-diag-error': { textDecorationColor: '#dc2626' },
  '.cm-diag-warning': { textDecorationColor: '#d97706' },
  '.cm-diag-info': { textDecorationColor: '#6b7280' },
  '.cm-diag-point': { display: 'inline-block', width: '0', height: '0.9em', verticalAlign: 'middle', borderLeft: '2px solid' },
  '.cm-diag-point-error': { borderColor: '#dc2626' },
  '.cm-diag-point-warning': { borderColor: '#d97706' },
  '.cm-diag-point-info': { borderColor: '#6b7280' },
  '.cm-diag-gutter .cm-gutterElement': { width: '0.9em', padding: '0' },
  '.cm-diag-marker': { width: '0.55em', height: '0.55em', borderRadius: '50%', margin: '0.45em auto 0' },
  '.cm-diag-marker-error': { background: '#dc2626' },
  '.cm-diag-marker-warning': { background: '#d97706' },
  '.cm-diag-marker-info': { background: '#9ca3af' },
  '.cm-diag-tip': { margin: '0', padding: '0.2em 0.5em', listStyle: 'none', maxWidth: '36em' },
  '.cm-diag-tip li': { padding: '0.1em 0 0.1em 0.5em', borderLeft: '3px solid' },
  '.cm-diag-tip-error': { borderColor: '#dc2626' },
  '.cm-diag-tip-warning': { borderColor: '#d97706' },
  '.cm-diag-tip-info': { borderColor: '#9ca3af' },
});

/** The extension: the underlines, their gutter, the tooltip and the keys. */
export function diagnostics() {
  return [
    field,
    gutter({ class: 'cm-diag-gutter', markers: (view) => view.state.field(field).lines }),
    tooltip,
    keymap.of([
      { key: 'F8', run: go(1) },
      { key: 'Shift-F8', run: go(-1) },
    ]),
    theme,
  ];
}

/** The transaction spec that shows `list` instead of the diagnostics shown. */
export function showDiagnostics(list) {
  return { effects: setList.of(list) };
}
