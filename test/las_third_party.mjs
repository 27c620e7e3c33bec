// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's LAS output read by a reader not written here: loaders.gl's LAS loader (npm
// package @loaders.gl/las, its LAS 1.4 path through laz-rs in WebAssembly), run by Node.js.
// Used by test_tool "tool: a third-party reader ..." (issue 45).
//
//   node test/las_third_party.mjs MODULES OUTPUT.las --las INPUT.las
//   node test/las_third_party.mjs MODULES OUTPUT.las --text INPUT.xyz
//
// MODULES: a node_modules folder holding @loaders.gl/las and @loaders.gl/core (e.g. after
// `npm install --prefix DIR @loaders.gl/las@4.5.1`, DIR/node_modules). Prints one line per
// fact: the header of OUTPUT as the reader sees it (version, point format, record length,
// count, scale, offset), then how its points compare with INPUT's: the largest difference of
// a coordinate (INPUT read by the same reader for --las, parsed from the text for --text: x y z
// the first three values of each line) and, for --las, the attributes read from both files
// that are equal point for point and those that differ. Exit status 1 if a file cannot be read.
// The loader gives positions as float32 and leaves out extra bytes (the estimates), so the
// estimates are not compared here; the record length counts them.

import {readFileSync} from 'fs';
import {join} from 'path';
import {pathToFileURL} from 'url';

const [modules, output, mode, input] = process.argv.slice(2);
if(!modules || !output || !['--las', '--text'].includes(mode) || !input) {
  console.error('usage: node las_third_party.mjs MODULES OUTPUT.las (--las INPUT.las | --text INPUT.xyz)');
  process.exit(2);
}
const load = (path) => import(pathToFileURL(join(modules, path)).href);
const core = await load('@loaders.gl/core/dist/index.js');
const las = await load('@loaders.gl/las/dist/index.js');
// the WebAssembly of laz-rs from its file (the loader would fetch it by URL, which Node cannot)
const wasm = join(modules, '@loaders.gl/las/dist/libs/laz-rs-wasm');
const init = (await load('@loaders.gl/las/dist/libs/laz-rs-wasm/laz_rs_wasm.js')).default;
await init({module_or_path: readFileSync(join(wasm, 'laz_rs_wasm_bg.wasm'))});

// the file as the loader gives it; exit status 1 if it cannot
async function read(path) {
  try {
    const bytes = readFileSync(path);
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
    return await core.parse(buffer, las.LAZRsLoader, {worker: false});
  } catch(error) {
    console.error(`cannot read ${path}: ${error.message}`);
    process.exit(1);
  }
}

const data = await read(output);
const header = data.loaderData;
console.log(`version ${header.versionAsString}`);
console.log(`format ${header.pointsFormatId}`);
console.log(`record_length ${header.pointsStructSize}`);
console.log(`count ${header.pointsCount} ${data.attributes.POSITION.value.length / 3}`);
console.log(`scale ${header.scale.join(' ')}`);
console.log(`offset ${header.offset.join(' ')}`);

const position = data.attributes.POSITION.value;
let expected;
if(mode === '--las') {
  const original = await read(input);
  console.log(`input_format ${original.loaderData.pointsFormatId}`);
  expected = original.attributes.POSITION.value;
  const equal = [], differ = [];
  for(const name of Object.keys(original.attributes).sort()) {
    if(name === 'POSITION')
      continue;
    const a = original.attributes[name].value, b = data.attributes[name] && data.attributes[name].value;
    const same = b !== undefined && a.length === b.length && a.every((v, i) => v === b[i]);
    (same ? equal : differ).push(name);
  }
  console.log(`attributes_equal ${equal.join(' ')}`);
  console.log(`attributes_differ ${differ.join(' ')}`);
} else {
  const values = [];
  for(const line of readFileSync(input, 'utf8').split('\n')) {
    const v = line.trim().split(/[\s,]+/).map(Number);
    if(v.length >= 3 && v.slice(0, 3).every(Number.isFinite))
      values.push(v[0], v[1], v[2]);
  }
  expected = Float64Array.from(values);
}
let difference = position.length === expected.length ? 0 : Infinity;
for(let i = 0; i < Math.min(position.length, expected.length); ++i)
  difference = Math.max(difference, Math.abs(position[i] - expected[i]));
console.log(`position_difference ${difference}`);
