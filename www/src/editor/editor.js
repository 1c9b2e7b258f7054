// The code pane: CodeMirror 6 with line numbers, undo/redo, find and
// replace (Ctrl-F, Ctrl-H… as CodeMirror's search keymap has them), G-code
// highlighting, diagnostics as underlines and gutter markers (message on
// hover), highlighted lines for what the pointer is over in a drawing, and
// a hint in an empty program.

import { defaultKeymap, history, historyKeymap } from '@codemirror/commands';
import { highlightSelectionMatches, search, searchKeymap } from '@codemirror/search';
import { Compartment, EditorState, RangeSetBuilder, StateEffect, StateField } from '@codemirror/state';
import { Decoration, drawSelection, EditorView, highlightActiveLine, highlightActiveLineGutter, keymap, lineNumbers, placeholder } from '@codemirror/view';
import { diagnostics, showDiagnostics } from './diagnostics.js';
import { gcode } from './gcode.js';

const setMarked = StateEffect.define();
const markLine = Decoration.line({ class: 'cm-marked' });
const markCall = Decoration.line({ class: 'cm-call' });

/** Lines marked from the drawings (hover, table rows). */
const marked = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    for (const e of tr.effects) if (e.is(setMarked)) return e.value;
    return deco.map(tr.changes);
  },
  provide: (f) => EditorView.decorations.from(f),
});

/** Runs `f` when the page is idle (after the next frame is out), or within 200 ms. */
function whenIdle(f) {
  if (typeof requestIdleCallback === 'function') requestIdleCallback(f, { timeout: 200 });
  else setTimeout(f, 16);
}

/**
 * Creates the editor in `parent`.
 * onChange(changes, before, after) runs on every document change, before
 * the editor shows it (a CodeMirror ChangeSet and the documents before and
 * after it; the editor's state is still `before`); onCursor(line) when the
 * cursor moves to another line.
 */
export function createEditor(parent, { doc, onChange, onCursor, words }) {
  // The editor's own words (search panel, empty-program hint) in the page's language.
  const language = new Compartment();
  const wordsOf = (w) => [EditorState.phrases.of((w && w.phrases) || {}), placeholder((w && w.empty) || '')];
  let lastLine = -1;
  let marks = ''; // the lines marked, as a key
  let markedDoc = null;
  let pending = null; // diagnostics to show after the frame: {list, changes made since}
  const view = new EditorView({
    parent,
    // The change goes to onChange before the editor updates its own view
    // (its document's lines, decorations, gutters): the engine plans while
    // the editor draws the typed character. The editor takes the change
    // whatever onChange does.
    dispatchTransactions(trs, v) {
      let changes = null;
      for (const tr of trs) if (tr.docChanged) changes = changes ? changes.compose(tr.changes) : tr.changes;
      try {
        if (changes) onChange(changes, v.state.doc, trs[trs.length - 1].state.doc);
      } finally {
        v.update(trs);
      }
    },
    state: EditorState.create({
      doc,
      extensions: [
        lineNumbers(),
        highlightActiveLineGutter(),
        history(),
        drawSelection(),
        highlightActiveLine(),
        gcode(),
        diagnostics(),
        marked,
        search({ top: true }),
        highlightSelectionMatches(),
        language.of(wordsOf(words)),
        keymap.of([...defaultKeymap, ...historyKeymap, ...searchKeymap]),
        EditorView.updateListener.of((u) => {
          if (u.docChanged) {
            if (pending) pending.changes = pending.changes ? pending.changes.compose(u.changes) : u.changes;
          }
          if (u.selectionSet || u.docChanged) {
            const line = u.state.doc.lineAt(u.state.selection.main.head).number;
            if (line !== lastLine || u.docChanged) {
              lastLine = line;
              // After this update: the handler may dispatch (line marks, diagnostics).
              queueMicrotask(() => onCursor(line));
            }
          }
        }),
        EditorView.theme({
          '&': { height: '100%' },
          '.cm-scroller': { fontFamily: 'ui-monospace, "Cascadia Mono", "Noto Sans Mono CJK SC", Menlo, monospace' },
        }),
      ],
    }),
  });

  function flush() {
    const p = pending;
    pending = null;
    if (!p) return;
    const m = p.changes;
    show(m ? p.list.map((d) => ({ ...d, from: m.mapPos(d.from, 1), to: m.mapPos(d.to, -1) })) : p.list);
  }

  function show(list) {
    view.dispatch(showDiagnostics(list));
  }

  return {
    view,
    text: () => view.state.doc.toString(),
    /** Replaces the whole program (one undoable change). */
    setText(text) {
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } });
    },
    /** Shows the plan's diagnostics (UTF-16 `from`/`to` as computed by the core). */
    setDiagnostics(list) {
      pending = null;
      show(list);
    },
    /**
     * Shows the diagnostics when the page is next idle, after the frame
     * (underlines and gutter marks are not worth delaying the drawings for),
     * mapped through the edits made meanwhile; a later call replaces an
     * earlier one not yet shown.
     */
    setDiagnosticsSoon(list) {
      const scheduled = pending !== null;
      pending = { list, changes: null };
      if (!scheduled) whenIdle(flush);
    },
    /**
     * Marks 1-based `lines` and, in another colour, the lines of the `calls`
     * that ran them (iterables), replacing the previous marks; the same
     * lines again change nothing.
     */
    markLines(lines, calls = []) {
      const doc = view.state.doc;
      const ok = (l) => l >= 1 && l <= doc.lines;
      const own = new Set([...lines].filter(ok));
      const sorted = [...new Set([...own, ...[...calls].filter(ok)])].sort((a, b) => a - b);
      const key = sorted.map((l) => (own.has(l) ? l : `c${l}`)).join(',');
      // Marks move with edits; an edit that joins or splits lines re-marks them.
      if (key === marks && doc === markedDoc) return;
      if (key === '' && marks === '') return;
      marks = key;
      markedDoc = doc;
      const b = new RangeSetBuilder();
      for (const l of sorted) {
        const line = doc.line(l);
        b.add(line.from, line.from, own.has(l) ? markLine : markCall);
      }
      view.dispatch({ effects: setMarked.of(b.finish()) });
    },
    /** Moves the cursor to `line`:`column` (1-based) and scrolls it into view. */
    goto(line, column = 1) {
      const doc = view.state.doc;
      const l = doc.line(Math.max(1, Math.min(line, doc.lines)));
      const pos = Math.min(l.from + Math.max(0, column - 1), l.to);
      view.dispatch({ selection: { anchor: pos }, scrollIntoView: true });
      view.focus();
    },
    cursorLine: () => view.state.doc.lineAt(view.state.selection.main.head).number,
    /** Sets the editor's own words (`{phrases, empty}`) in another language. */
    setWords: (w) => view.dispatch({ effects: language.reconfigure(wordsOf(w)) }),
  };
}
