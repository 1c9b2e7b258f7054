// G-code highlighting for CodeMirror 6: comments in parentheses or after
// ';', program numbers and '%' lines, sequence numbers, G and M codes, axis
// and other words with their numbers. Full-width characters (Ｇ３２, ；, （）)
// are read like their ASCII twins.
//
// A block is one line and a comment ends with its line (as the planner reads
// them), so every line is highlighted on its own, and only the lines the
// editor shows: an edit costs the same in a program of any length, with no
// parse of the whole document behind it.

import { StringStream } from '@codemirror/language';
import { EditorState, Prec, RangeSetBuilder } from '@codemirror/state';
import { Decoration, EditorView, ViewPlugin } from '@codemirror/view';

const FULL = /[\uFF01-\uFF5E]/;
const ascii = (c) => (c && FULL.test(c) ? String.fromCharCode(c.charCodeAt(0) - 0xfee0) : c);

const gcodeParser = {
  name: 'gcode',
  startState: () => ({ comment: false }),
  token(stream, state) {
    if (state.comment) {
      while (!stream.eol()) {
        const c = ascii(stream.next());
        if (c === ')') {
          state.comment = false;
          break;
        }
      }
      return 'comment';
    }
    if (stream.eatSpace()) return null;
    const c = ascii(stream.peek());
    if (c === '(') {
      stream.next();
      state.comment = true;
      while (!stream.eol()) {
        if (ascii(stream.next()) === ')') {
          state.comment = false;
          break;
        }
      }
      return 'comment';
    }
    if (c === ';') {
      stream.skipToEnd();
      return 'comment';
    }
    if (c === '%') {
      stream.skipToEnd();
      return 'meta';
    }
    const letter = c && c.toUpperCase();
    if (letter && /[A-Z]/.test(letter)) {
      stream.next();
      const start = stream.pos;
      while (!stream.eol() && /[0-9.+-]/.test(ascii(stream.peek()))) stream.next();
      const hasNumber = stream.pos > start;
      if (letter === 'O') return 'meta';
      if (letter === 'N') return 'labelName';
      if (!hasNumber) return 'invalid';
      if (letter === 'G') return 'keyword';
      if (letter === 'M') return 'atom';
      if ('XZUW'.includes(letter)) return 'variableName';
      if ('FIS'.includes(letter)) return 'propertyName';
      return 'number';
    }
    stream.next();
    return /[0-9.+-]/.test(c) ? 'number' : 'invalid';
  },
  blankLine(state) {
    state.comment = false;
  },
};

/** Colours of the token types. */
const COLOURS = {
  comment: { color: '#6b7280', fontStyle: 'italic' },
  keyword: { color: '#1d4ed8', fontWeight: '600' },
  atom: { color: '#7c3aed', fontWeight: '600' },
  variableName: { color: '#b45309' },
  propertyName: { color: '#047857' },
  labelName: { color: '#9ca3af' },
  meta: { color: '#be185d' },
  number: { color: '#0f766e' },
  invalid: { color: '#dc2626', textDecoration: 'underline wavy' },
};
const MARKS = Object.fromEntries(Object.keys(COLOURS).map((k) => [k, Decoration.mark({ class: `cm-g-${k}` })]));

/** Calls `emit(from, to, type)` for every token of one line (a fresh state: comments end with the line). */
export function tokens(text, emit) {
  const stream = new StringStream(text, 4, 2);
  const state = gcodeParser.startState();
  while (!stream.eol()) {
    stream.start = stream.pos;
    const type = gcodeParser.token(stream, state);
    if (stream.pos === stream.start) stream.next();
    if (type && MARKS[type]) emit(stream.start, stream.pos, type);
  }
}

/** The marks of the lines in the editor's viewport. */
function marks(view) {
  const b = new RangeSetBuilder();
  const doc = view.state.doc;
  const { from, to } = view.viewport;
  for (let pos = from; pos <= to; ) {
    const line = doc.lineAt(pos);
    tokens(line.text, (a, e, type) => b.add(line.from + a, line.from + e, MARKS[type]));
    pos = line.to + 1;
  }
  return b.finish();
}

const highlighter = ViewPlugin.fromClass(
  class {
    constructor(view) {
      this.decorations = marks(view);
    }

    update(u) {
      if (u.docChanged || u.viewportChanged) this.decorations = marks(u.view);
    }
  },
  { decorations: (p) => p.decorations },
);

/** G-code highlighting, its colours and its comment token (for toggle-comment). */
export function gcode() {
  const theme = EditorView.baseTheme(Object.fromEntries(Object.entries(COLOURS).map(([k, v]) => [`.cm-g-${k}`, v])));
  // Lowest precedence: the token marks sit inside every other mark (the
  // diagnostics' underlines). Outside them, a key typed just after an
  // underlined word and deleted again made CodeMirror redraw every line in
  // view (some 260 DOM changes instead of one).
  return [Prec.lowest(highlighter), theme, EditorState.languageData.of(() => [{ commentTokens: { line: ';' } }])];
}

export { gcodeParser };
