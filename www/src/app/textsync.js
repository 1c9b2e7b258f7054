// What the engine holds of the program. A keystroke sends the engine the
// changes since the text it holds, not the whole text: copying a long
// program into a message on every keystroke held up the page (about 2 ms at
// 5,000 lines, ten times that at 50,000). The engine applies them
// (engine.js `applyEdits`) and checks the length; a document the engine was
// never sent, or one reached by changes not followed here (another editor),
// goes whole.

export class TextSync {
  constructor() {
    this.reset();
  }

  /** Forgets what the engine holds: the next text goes whole. */
  reset() {
    this.sent = null; // the document last sent
    this.at = null; // the document `changes` lead to
    this.changes = null; // a CodeMirror ChangeSet from `sent` to `at` (null: none)
  }

  /** The editor's document `before` became `after` by `changes` (a CodeMirror ChangeSet). */
  changed(changes, before, after) {
    if (this.sent === null) return;
    if (before !== this.at) {
      this.reset();
      return;
    }
    this.changes = this.changes ? this.changes.compose(changes) : changes;
    this.at = after;
  }

  /**
   * What a plan message carries of document `doc` (a CodeMirror Text), now
   * sent: `{edits: [[from, to, inserted]...], length}` (UTF-16 offsets in
   * the text the engine holds, in order; `length` the new text's) when the
   * engine holds a document that the changes followed here lead to `doc`
   * from, else `{text}`.
   */
  take(doc) {
    let out;
    if (this.sent !== null && this.at === doc) {
      const edits = [];
      if (this.changes) this.changes.iterChanges((fromA, toA, _fromB, _toB, inserted) => edits.push([fromA, toA, inserted.toString()]));
      out = { edits, length: doc.length };
    } else {
      out = { text: doc.toString() };
    }
    this.sent = doc;
    this.at = doc;
    this.changes = null;
    return out;
  }
}
