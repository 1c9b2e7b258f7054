// Side by side in Node: the cncjs gcode-toolpath package and screwcut's wasm
// build interpret the same generated programs; the native figures come from
// `cargo bench --bench throughput`. Usage: node toolpath.mjs PKG_DIR FILE...
// Prints rates and screwcut's speed as a multiple of gcode-toolpath's.
import { readFileSync } from 'node:fs';
import Toolpath from 'gcode-toolpath';

const [pkg, ...files] = process.argv.slice(2);
const mod = await import(pkg + '/screwcut.js');
mod.initSync({ module: readFileSync(pkg + '/screwcut_bg.wasm') });

function best(runs, f) {
  let b = Infinity;
  let out;
  for (let i = 0; i < runs; i++) {
    const t = performance.now();
    out = f();
    b = Math.min(b, performance.now() - t);
  }
  return [b, out];
}

/** gcode-toolpath as a viewer uses it: every line and arc becomes a segment object. */
function toolpath(text) {
  const segments = [];
  const tp = new Toolpath({
    modal: { plane: 'G18' },
    addLine: (modal, v1, v2) => segments.push({ motion: modal.motion, v1, v2 }),
    addArcCurve: (modal, v1, v2, v0) => segments.push({ motion: modal.motion, v1, v2, v0 }),
  });
  tp.loadFromStringSync(text, () => {});
  return segments.length;
}

/** screwcut in wasm: plan (with the app's scenes) and read every motion as a typed array. */
function screwcut(text) {
  mod.update(text, 'gsk980tdc', '', -1, 1, -1);
  return mod.moves().length;
}

// Native rates measured by `cargo bench --bench throughput` in the same run, passed by xtask.
const native = Object.fromEntries((process.env.NATIVE_RATES || '').split(',').filter(Boolean).map((kv) => {
  const [k, v] = kv.split('=');
  return [k, Number(v)];
}));
const rows = [];
for (const file of files) {
  const text = readFileSync(file, 'utf8');
  const mb = text.length / 1e6;
  const runs = text.length > 4e6 ? 2 : 5;
  const [tpMs, tpSegs] = best(runs, () => toolpath(text));
  const [scMs] = best(runs, () => screwcut(text));
  const name = file.split('/').pop();
  rows.push({ name, mb, tpMs, scMs });
  if (native[name]) {
    const tpRate = mb / tpMs * 1e3;
    console.log(`  ${name}: screwcut native ${native[name].toFixed(1)} MB/s = ${(native[name] / tpRate).toFixed(1)}× gcode-toolpath (${tpRate.toFixed(1)} MB/s)`);
  }
  console.log(
    `  ${name}: gcode-toolpath ${tpMs.toFixed(0)} ms (${(mb / tpMs * 1e3).toFixed(1)} MB/s, ${tpSegs} segments); ` +
      `screwcut wasm in Node ${scMs.toFixed(0)} ms (${(mb / scMs * 1e3).toFixed(1)} MB/s) = ${(tpMs / scMs).toFixed(1)}× gcode-toolpath`,
  );
}
console.log('JSON ' + JSON.stringify(rows));
