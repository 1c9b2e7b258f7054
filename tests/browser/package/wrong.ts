// Uses the types wrongly: this file must NOT type-check (the declarations are not `any`).
import type { ScrewcutPreview } from 'screwcut-preview';

declare const el: ScrewcutPreview;
const alarms: string = el.result ? el.result.alarms : '';
el.addEventListener('screwcut-plan', (e) => e.detail.passes.length);
el.start(1);
console.log(alarms);
