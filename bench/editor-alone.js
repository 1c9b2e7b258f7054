// The project's own editor alone (`www/src/editor/editor.js`, the same
// CodeMirror setup as the app's code pane) on a page with the app's
// stylesheet and the app's code pane size, changes going nowhere: the floor
// a keystroke in the app is measured against (`cargo xtask bench`).
// Query: program=URL of the text, w and h = the app's code pane in CSS px.
import { createEditor } from '../www/src/editor/editor.js';

const q = new URLSearchParams(location.search);
const text = await (await fetch(q.get('program'))).text();
const code = document.getElementById('code');
code.style.width = `${Number(q.get('w')) || 600}px`;
code.style.height = `${Number(q.get('h')) || 800}px`;
const editor = createEditor(document.getElementById('editor'), { doc: text, onChange() {}, onCursor() {}, words: null });
window.__screwcut = { editor: () => editor };
document.body.dataset.ready = 'true';
