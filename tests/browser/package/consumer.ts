// A page's script using the package's types: each use below must type-check.
import { ScrewcutPreview } from 'screwcut-preview';
import type { ScrewcutPass, ScrewcutPlanDetail } from 'screwcut-preview';

const el: ScrewcutPreview | null = document.querySelector('screwcut-preview');
if (el) {
  el.program = 'G00 X58. Z70.\nG92 X47.1 Z13. F2.\n';
  el.start();
  el.addEventListener('screwcut-plan', (e) => {
    const d: ScrewcutPlanDetail = e.detail;
    const passes: ScrewcutPass[] = el.result ? el.result.passes : [];
    const first: [number, number] | undefined = passes[0]?.from;
    console.log(d.alarms + d.warnings, first, el.problems.map((p) => p.attribute));
  });
}
const made = document.createElement('screwcut-preview');
made.setAttribute('view', 'side tooth');
console.log(made instanceof ScrewcutPreview);
