/**
 * Fuzz target `gldf` (issue 31): GLDF containers through the whole import
 * (importGldfCatalog: zip reader, product.xml, conversion, the photometry parsers, the
 * catalog's own validation) into the demo catalog. Seeds: the tests' track spot, pendant and
 * linear module (tests/core/gldf/buildGldf.ts, from the repository's photometry). Most mutants
 * change product.xml inside a well-formed container (gldfCodec), so they reach the XML and the
 * id checks rather than stopping at a checksum; raw container bytes are mutated too. Accepted
 * means a complete catalog: it validates again after a JSON round trip, holds no non-finite
 * number, and every photometry (and L3D model) it names is among the files the import returns or the base's.
 */
import { readFileSync } from 'node:fs';
import { unzipSync, zipSync } from 'fflate';
import { GldfError } from '../../src/core/gldf/GldfError';
import { importGldfCatalog } from '../../src/core/gldf/importGldfCatalog';
import { InputError } from '../../src/core/inputError';
import { parseCatalog, parseCatalogText } from '../../src/core/model/catalogSchema/catalogSchema';
import { gldfBytes, linearSpec, pendantSpec, trackSpotSpec, type GldfSpec } from '../core/gldf/buildGldf';
import { nonFinitePaths } from './checks';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

const SPECS: [string, () => GldfSpec][] = [
  ['track-spot.gldf', trackSpotSpec],
  ['pendant.gldf', pendantSpec],
  ['linear.gldf', linearSpec],
];

let others: Record<string, Uint8Array> | null = null;
/** Every file any seed holds besides product.xml: a mutated product.xml is zipped with all of them. */
function otherEntries(): Record<string, Uint8Array> {
  if (!others) {
    others = {};
    for (const [, spec] of SPECS) {
      const entries = unzipSync(gldfBytes(spec()));
      for (const [name, bytes] of Object.entries(entries)) if (name !== 'product.xml') others[name] = bytes;
    }
  }
  return others;
}

/** product.xml out of a container and back into one (the CODECS entry in fuzzEngine.ts). */
export const gldfCodec = {
  decode(zip: Uint8Array): Uint8Array | null {
    try {
      return unzipSync(zip, { filter: (f) => f.name === 'product.xml' })['product.xml'] ?? null;
    } catch {
      return null;
    }
  },
  encode: (xml: Uint8Array): Uint8Array => zipSync({ ...otherEntries(), 'product.xml': xml }, { mtime: new Date('2026-11-27T08:00:00Z') }),
};

let base: ReturnType<typeof parseCatalogText> | null = null;

export const gldfFuzzTarget: FuzzTarget = {
  name: 'gldf',
  seeds: (): FuzzSeed[] => SPECS.map(([name, spec]) => ({ name, bytes: gldfBytes(spec()) })),
  run(input: Uint8Array): FuzzOutcome {
    base ??= parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'));
    let result: ReturnType<typeof importGldfCatalog>;
    try {
      result = importGldfCatalog(base, [{ name: 'fuzz.gldf', bytes: input }], null);
    } catch (error) {
      if (error instanceof GldfError || error instanceof InputError) return { kind: 'refused', message: error.message };
      throw error;
    }
    const problems = nonFinitePaths(result.catalog).map((p) => `non-finite ${p}`);
    const roundTrip = parseCatalog(JSON.parse(JSON.stringify(result.catalog)));
    if (JSON.stringify(roundTrip) !== JSON.stringify(result.catalog)) problems.push('partial catalog: changes on a JSON round trip');
    const files = new Set(result.files.map((f) => f.path));
    const baseFiles = new Set(base.moduleTypes.flatMap((t) => t.beams.map((b) => b.photometry)));
    for (const b of result.catalog.moduleTypes.flatMap((t) => t.beams)) if (!files.has(b.photometry) && !baseFiles.has(b.photometry)) problems.push(`partial catalog: ${b.photometry} not written`);
    // An L3D body the catalog names is written too (the track spot carries one).
    for (const t of result.catalog.moduleTypes) if (t.model && !files.has(t.model)) problems.push(`partial catalog: ${t.model} not written`);
    if (result.report.products.every((p) => p.typeId === null)) problems.push('partial catalog: accepted with no module type');
    return { kind: 'accepted', problems };
  },
};
