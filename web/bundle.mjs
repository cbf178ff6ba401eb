// Bundles the page's viewer (src/main.js with three.js) with esbuild's API and writes it
// as C++ raw string literals for engine/web's generated source, with "</script"
// escaped so that the bundle can sit inside the page's <script> element.
// usage: node web/bundle.mjs OUT.js OUT.inc
import { build } from 'esbuild';
import { readFileSync, writeFileSync, renameSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const [, , outJs, outInc] = process.argv;
await build({
  entryPoints: [join(dirname(fileURLToPath(import.meta.url)), 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'none',
  logLevel: 'warning',
  outfile: outJs,
});
const js = readFileSync(outJs, 'utf8').replace(/<\/script/gi, '<\\/script');
const close = ')pwjs"';
if (js.includes(close)) throw new Error(`${outJs} holds ${close}: pick another raw string delimiter`);
const parts = [];
for (let at = 0; at < js.length; at += 16000) parts.push('R"pwjs(' + js.slice(at, at + 16000) + close);
writeFileSync(outInc + '.tmp', parts.join('\n') + '\n');
renameSync(outInc + '.tmp', outInc);
