// Extracts the colour-filter library (src/core/colour/colour-filters.json) from the dataset of the
// PyPI package lighting_filters 0.1.1 (MIT, Reid Sox-Harris; the data belong to the manufacturers,
// here LEE Filters, published on leefilters.com). Not run in CI: the dataset is not in the repository.
// Usage: pip download lighting_filters==0.1.1 --no-deps, unzip the wheel, then
//   node scripts/extractColourFilters.mjs /path/to/dataset/filters.json
// The curves are copied as published (405–700 nm at 5 nm, the range the dataset holds): nothing is
// interpolated or extended here; src/core/colour/colourFilterLibrary.ts says how the colorimetry
// treats the wavelengths outside the measured range (docs/colour-filters.md).
import { createHash } from 'node:crypto';
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';

const root = resolve(new URL('..', import.meta.url).pathname);
const input = process.argv[2] ?? '/tmp/pipdl/lf/dataset/filters.json';
// Two files (docs/colour-filters.md, "Two files"): the index (ids and names: the planner's first screen
// needs it to validate and list filters) and the spectra with their provenance (loaded when a
// colour is computed, so the first screen does not carry ~10 KiB of curves).
const indexOutput = resolve(root, 'src/core/colour/colour-filters.json');
const spectraOutput = resolve(root, 'src/core/colour/colour-filter-spectra.json');

/** Dataset key → kind. CTO/CTB in every strength LEE sells, neutral densities, and common colours. */
const PICK = {
  cto: ['L204', 'L285', 'L205', 'L206', 'L223'],
  ctb: ['L201', 'L281', 'L202', 'L203', 'L218'],
  nd: ['L298', 'L209', 'L210', 'L211'],
  colour: [
    // reds and pinks
    'L106',
    'L026',
    'L164',
    'L182',
    'L002',
    'L035',
    'L128',
    'L113',
    // ambers, oranges, yellows
    'L020',
    'L104',
    'L105',
    'L147',
    'L162',
    'L101',
    'L010',
    // greens
    'L139',
    'L121',
    'L138',
    'L124',
    // blues
    'L119',
    'L132',
    'L118',
    'L117',
    'L068',
    'L181',
    // lavenders and violets
    'L058',
    'L052',
    'L136',
    'L142',
  ],
};

const text = readFileSync(input, 'utf8');
const data = JSON.parse(text);
if (data.version !== '0.2.0') throw new Error(`${input}: expected dataset version 0.2.0, found ${data.version}`);

const num = (s, what) => {
  const x = Number(s);
  if (!Number.isFinite(x)) throw new Error(`${what}: '${s}' is not a number`);
  return x;
};
/** CIE x, y and Y (Y in per cent, as published) of the filter under the dataset's source A / source C. */
const stated = (c, key) => (c ? { x: num(c.x, `${key} x`), y: num(c.y, `${key} y`), Y: num(c.Y, `${key} Y`) } : undefined);

const filters = [];
for (const [kind, keys] of Object.entries(PICK)) {
  for (const key of keys) {
    const f = data.filters[key];
    if (!f) throw new Error(`${input}: no filter ${key}`);
    if (!f.brand.startsWith('Lee') || !f.sd) throw new Error(`${key}: expected a LEE filter with spectral data`);
    const nms = Object.keys(f.sd)
      .map(Number)
      .sort((a, b) => a - b);
    const start = nms[0];
    nms.forEach((nm, i) => {
      if (nm !== start + 5 * i) throw new Error(`${key}: wavelengths are not a 5 nm grid at ${nm} nm`);
    });
    filters.push({
      id: `lee-${key.slice(1)}`,
      maker: 'LEE Filters',
      number: key.slice(1),
      name: f.name,
      kind,
      startNm: start,
      stepNm: 5,
      transmission: nms.map((nm) => num(f.sd[String(nm)], `${key} ${nm} nm`)),
      stated: { sourceA: stated(f.src_a, `${key} src_a`), sourceC: stated(f.src_c, `${key} src_c`) },
      source: 'https://leefilters.com/',
      datasetKey: key,
    });
  }
}

const index = {
  formatVersion: 2,
  filters: filters.map(({ id, maker, number, name, kind }) => ({ id, maker, number, name, kind })),
};
const spectra = {
  formatVersion: 1,
  dataset: {
    name: 'lighting_filters 0.1.1 (PyPI), dataset/filters.json',
    url: 'https://pypi.org/project/lighting-filters/0.1.1/',
    licence: 'MIT, Copyright (c) 2025 Reid Sox-Harris; filter data owned by the manufacturers (LEE Filters), publicly provided to end users',
    sha256: createHash('sha256').update(text).digest('hex'),
  },
  spectra: filters.map(({ id, startNm, stepNm, transmission, stated, source, datasetKey }) => ({ id, startNm, stepNm, transmission, stated, source, datasetKey })),
};
// One filter's curve on one line: the file stays readable and diffs name the filter that changed.
const write = (path, data) => writeFileSync(path, `${JSON.stringify(data, null, 1).replace(/\[\n\s*([-\d.,\s]+?)\n\s*\]/g, (_, body) => `[${body.split(/,\s*/).join(', ')}]`)}\n`);
write(indexOutput, index);
write(spectraOutput, spectra);
console.log(`wrote ${filters.length} filters to ${indexOutput} and ${spectraOutput}`);
