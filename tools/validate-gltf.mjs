#!/usr/bin/env node
// Runs the Khronos glTF-Validator (npm package gltf-validator, installed into
// tools/node_modules by scripts/install-tools.sh) on each file given.
// Prints, per file, the counts of errors, warnings, infos and hints and every error
// and warning; exits 1 when any file has an error, 2 when a file cannot be read or
// the validator is missing, 0 otherwise.
// Usage: node tools/validate-gltf.mjs FILE.glb|FILE.gltf...
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const require = createRequire(import.meta.url);
let validator;
try {
  validator = require('gltf-validator');
} catch {
  console.error('validate-gltf: gltf-validator is not installed; run scripts/install-tools.sh');
  process.exit(2);
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node tools/validate-gltf.mjs FILE.glb|FILE.gltf...');
  process.exit(2);
}

let worst = 0;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(await readFile(file));
  } catch (e) {
    console.error(`${file}: cannot read: ${e.message}`);
    worst = Math.max(worst, 2);
    continue;
  }
  let report;
  try {
    report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0,  // report everything
      writeTimestamp: false,
      // Resources beside a .gltf (a .bin, images) are validated too.
      externalResourceFunction: (uri) =>
        readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
    });
  } catch (e) {
    console.error(`${file}: the validator could not read it: ${e}`);
    worst = Math.max(worst, 2);
    continue;
  }
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
  const severityNames = ['error', 'warning', 'info', 'hint'];
  for (const m of messages) {
    if (m.severity <= 1) console.log(`  ${severityNames[m.severity]} ${m.code} at ${m.pointer ?? '-'}: ${m.message}`);
  }
  if (numErrors > 0) worst = Math.max(worst, 1);
}
process.exit(worst);
