// Turns three's ES module build (build/three.module.min.js) and its OrbitControls
// (examples/jsm/controls/OrbitControls.js) into ONE classic script defining `THREE` (with
// THREE.OrbitControls), so that the HTML report can inline it: an inline module cannot import
// another inline module, and the page must make no request at all. Keeps three's MIT licence
// text in a leading comment.
//   node tools/html/bundle_three.mjs node_modules/three OUT.js
import fs from 'node:fs';
import path from 'node:path';

const [threeDir, out] = process.argv.slice(2);
if (!threeDir || !out) {
  console.error('usage: bundle_three.mjs THREE_PACKAGE_DIR OUT.js');
  process.exit(2);
}
const read = (p) => fs.readFileSync(path.join(threeDir, p), 'utf8');
const pkg = JSON.parse(read('package.json'));
const licence = read('LICENSE').trim();

// three.module.min.js: no imports, one trailing `export{a as B,...};`.
let core = read('build/three.module.min.js');
const ex = core.match(/export\s*\{([^}]*)\}\s*;?\s*$/);
if (!ex) throw new Error('three.module.min.js: trailing export list not found');
core = core.slice(0, ex.index);
if (/^\s*import[\s{*]/m.test(core) || /import\.meta/.test(core)) throw new Error('three.module.min.js imports something');
const names = ex[1].split(',').map((s) => s.trim()).filter(Boolean).map((e) => {
  const m = e.split(/\s+as\s+/);
  return m.length === 2 ? `${JSON.stringify(m[1])}:${m[0]}` : `${m[0]}:${m[0]}`;
});

// OrbitControls.js: `import {...} from 'three';` ... `export { OrbitControls };`
let orbit = read('examples/jsm/controls/OrbitControls.js');
const im = orbit.match(/import\s*\{([^}]*)\}\s*from\s*['"]three['"]\s*;?/);
if (!im) throw new Error('OrbitControls.js: import from three not found');
orbit = orbit.replace(im[0], `const {${im[1]}} = THREE;`);
const before = orbit.length;
orbit = orbit.replace(/export\s*\{\s*OrbitControls\s*\}\s*;?/, '');
if (orbit.length === before || /^\s*(import|export)\b/m.test(orbit)) throw new Error('OrbitControls.js: unexpected module syntax');

const text =
  `/*! three.js ${pkg.version} - npm package three@${pkg.version}: build/three.module.min.js and\n` +
  ` * examples/jsm/controls/OrbitControls.js, made one classic script by tools/html/bundle_three.mjs.\n` +
  ` * three.js licence:\n *\n` + licence.split('\n').map((l) => ` * ${l}`.trimEnd()).join('\n') + '\n */\n' +
  `var THREE = (function () {\n"use strict";\n${core}\nreturn {${names.join(',')}};\n})();\n` +
  `THREE.OrbitControls = (function () {\n"use strict";\n${orbit}\nreturn OrbitControls;\n})();\n`;
if (/<\/script/i.test(text)) throw new Error('bundle contains </script');
fs.writeFileSync(out, text);
