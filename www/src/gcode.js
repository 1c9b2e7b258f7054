// G-code highlighting for CodeMirror 6 as a stream language: comments in
// parentheses or after ';', program numbers and '%' lines, sequence numbers,
// G and M codes, axis and other words with their numbers. Full-width
// characters (Ｇ３２, ；, （）) are read like their ASCII twins.

import { StreamLanguage, HighlightStyle, syntaxHighlighting } from '@codemirror/language';
import { tags } from '@lezer/highlight';

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
      while (!stream.eol() && /[0-9.+\-]/.test(ascii(stream.peek()))) stream.next();
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
    return /[0-9.+\-]/.test(c) ? 'number' : 'invalid';
  },
  blankLine(state) {
    state.comment = false;
  },
  languageData: { commentTokens: { line: ';' } },
};

/** The G-code language and its colours. */
export function gcode() {
  const style = HighlightStyle.define([
    { tag: tags.comment, color: '#6b7280', fontStyle: 'italic' },
    { tag: tags.keyword, color: '#1d4ed8', fontWeight: '600' },
    { tag: tags.atom, color: '#7c3aed', fontWeight: '600' },
    { tag: tags.variableName, color: '#b45309' },
    { tag: tags.propertyName, color: '#047857' },
    { tag: tags.labelName, color: '#9ca3af' },
    { tag: tags.meta, color: '#be185d' },
    { tag: tags.number, color: '#0f766e' },
    { tag: tags.invalid, color: '#dc2626', textDecoration: 'underline wavy' },
  ]);
  return [StreamLanguage.define(gcodeParser), syntaxHighlighting(style)];
}

export { gcodeParser };
