// The shadow DOM styles of <screwcut-preview>: nothing leaks to the page,
// and the page reaches in only through the custom properties below.
//
//   --screwcut-border   frame colour         (default #d1d5db)
//   --screwcut-bg       drawing background   (default #fff)
//   --screwcut-accent   link and focus colour (default #1d4ed8)
//
// Parts: ::part(box) the frame, ::part(code) the listing, ::part(open) the
// link, ::part(fallback) the static drawings and table shown until the live
// ones are ready (and in print, while they show the element's program).

export const STYLE = `
:host { display: block; margin: 1em 0; color: #111827; font: 13px/1.4 system-ui, -apple-system, "Segoe UI", "Noto Sans CJK SC", "Microsoft YaHei", sans-serif; }
:host([hidden]) { display: none; }
* { box-sizing: border-box; }
.box { position: relative; border: 1px solid var(--screwcut-border, #d1d5db); border-radius: 6px; background: var(--screwcut-bg, #fff); overflow: hidden; container-type: inline-size; }
/* Two drawings share a row; three put the side section on a row of its own
   and the tooth and starts side by side under it; a drawing alone, and the
   pass table (it needs the width for its columns), take whole rows. A
   narrow element has one column. No cell is left empty. */
.views { display: grid; grid-template-columns: repeat(2, minmax(0, 1fr)); grid-auto-flow: row dense; gap: 1px; background: var(--screwcut-border, #d1d5db); }
.views > .view.table,
.views > .view:only-child,
.views:not(:has(> .view:not(.table) ~ .view:not(.table))) > .view,
.views:has(> [data-view="tooth"]):has(> [data-view="starts"]) > [data-view="side"] { grid-column: 1 / -1; }
@container (max-width: 560px) { .views { grid-template-columns: minmax(0, 1fr); } }
/* The static drawings placed inside the element (screwcut embed's) and its
   static pass table show, each in its view's place with its caption, until
   the live views are drawn: nothing moves when they come. Without script
   the page shows them as they are. */
.box:not(.static) > .views.fallback { display: none; }
.box.static > .views.live { visibility: hidden; height: 0; overflow: hidden; }
.views.fallback ::slotted(svg) { display: block; flex: 1 1 0; min-height: 0; width: 100%; height: auto; }
.views.fallback .view.table table { font: inherit !important; font-size: 12px !important; }
/* In print the static drawing stands for the live one while it shows the same program. */
@media print {
  .box.printable > .views.fallback { display: grid; }
  .box.printable > .views.fallback > .view.table { max-height: none; }
  .box.printable > .views.live > .view:not(.table) { display: none; }
  .box.printable.static-table > .views.live > .view.table { display: none; }
}
.view { position: relative; background: var(--screwcut-bg, #fff); min-width: 0; height: var(--h, 320px); display: flex; flex-direction: column; }
/* A drawing's caption is a line above its canvas, so that no label goes under it. */
.view canvas { display: block; width: 100%; flex: 1; min-height: 0; cursor: grab; touch-action: pan-y; }
.view .cap { order: -1; padding: 3px 6px 0; line-height: 14px; font-size: 11px; color: #6b7280; pointer-events: none; }
.view.table .cap { position: absolute; left: 6px; top: 4px; padding: 0; }
.view.table { display: block; overflow: auto; padding-top: 20px; height: auto; max-height: var(--h, 320px); }
.wait { display: flex; align-items: center; justify-content: center; color: #9ca3af; }
table { border-collapse: collapse; width: 100%; font-variant-numeric: tabular-nums; font-size: 12px; }
th, td { padding: 2px 6px; text-align: right; border-bottom: 1px solid #f3f4f6; white-space: nowrap; }
th { position: sticky; top: 0; background: #f9fafb; font-weight: 600; }
td.role, th.role, td.lines { text-align: left; }
tr.finish td.role { color: #047857; font-weight: 600; }
tr.spring td.role { color: #6d28d9; font-weight: 600; }
tbody tr.hot { background: #fef3c7; }
pre.code { margin: 0; max-height: 17.5em; overflow: auto; border-top: 1px solid var(--screwcut-border, #d1d5db); padding: 6px 0; font: 12.5px/1.45 ui-monospace, "Cascadia Mono", "Noto Sans Mono CJK SC", Menlo, monospace; background: #fcfcfd; counter-reset: line; }
pre.code span { display: block; padding: 0 8px 0 0; white-space: pre; }
pre.code span::before { counter-increment: line; content: counter(line); display: inline-block; width: 3.2em; padding-right: 0.8em; text-align: right; color: #9ca3af; user-select: none; }
pre.code span.hot { background: #fde68a; }
textarea { display: block; width: 100%; min-height: 9em; resize: vertical; border: 0; border-top: 1px solid var(--screwcut-border, #d1d5db); padding: 6px 8px; font: 12.5px/1.45 ui-monospace, "Cascadia Mono", "Noto Sans Mono CJK SC", Menlo, monospace; color: inherit; background: #fcfcfd; tab-size: 4; }
textarea:focus { outline: 2px solid var(--screwcut-accent, #1d4ed8); outline-offset: -2px; }
.bar { display: flex; flex-wrap: wrap; align-items: center; gap: 4px 10px; padding: 4px 8px; border-top: 1px solid var(--screwcut-border, #d1d5db); background: #f9fafb; font-size: 12px; color: #374151; }
.bar .sum { flex: 1; min-width: 12em; }
.bar select { font: inherit; font-size: 12px; max-width: 24em; }
.bar a { color: var(--screwcut-accent, #1d4ed8); text-decoration: none; font-weight: 600; white-space: nowrap; }
.bar a:hover { text-decoration: underline; }
.stale { color: #991b1b; }
ul.diags { list-style: none; margin: 0; padding: 0; font-size: 12px; border-top: 1px solid var(--screwcut-border, #d1d5db); max-height: 8.5em; overflow: auto; }
ul.diags:empty { display: none; }
ul.diags li { padding: 2px 8px; border-bottom: 1px solid #f3f4f6; }
ul.diags li.error b { color: #b91c1c; }
ul.diags li.warning b { color: #b45309; }
ul.diags li.info b { color: #2563eb; }
ul.diags[data-editable] li { cursor: pointer; }
ul.diags code { color: #6b7280; }
.tip { position: absolute; z-index: 2; pointer-events: none; max-width: 90%; padding: 3px 7px; background: #111827; color: #f9fafb; border-radius: 4px; font-size: 12px; box-shadow: 0 2px 6px rgba(0,0,0,0.25); }
.tip[hidden] { display: none; }
`;
