// Validates a .glb or .gltf with the Khronos glTF-Validator (npm gltf-validator, fetched by
// scripts/fetch-gltf-validator.sh): prints every message it reports, one per line, then the counts, and exits 1 when
// it found an error or a warning. Usage: node validate_gltf.js FILE
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate_gltf.js FILE');
  process.exit(2);
}
const bytes = new Uint8Array(fs.readFileSync(file));
validator
  .validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    // A .glb carries its buffers; a .gltf's external files are read beside it.
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)));
      }),
  })
  .then((report) => {
    const names = ['error', 'warning', 'info', 'hint'];
    for (const m of report.issues.messages)
      console.log(`${names[m.severity] || m.severity}: ${m.code} at ${m.pointer || '-'}: ${m.message}`);
    const i = report.issues;
    console.log(`errors ${i.numErrors} warnings ${i.numWarnings} infos ${i.numInfos} hints ${i.numHints}`);
    process.exit(i.numErrors > 0 || i.numWarnings > 0 ? 1 : 0);
  })
  .catch((e) => {
    console.error('the validator failed: ' + e);
    process.exit(2);
  });
