/**
 * Fuzz target: catalog files (what a manufacturer supplies, docs/catalog-format.md)
 * through parseCatalogText. Seed: the demo catalog.
 */
import { readFileSync } from 'node:fs';
import { CatalogError, parseCatalogText, type Catalog } from '../../src/core/model/catalogSchema/catalogSchema';
import { jsonAcceptedProblems } from './checks';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

const decoder = new TextDecoder('utf-8');

export const catalogFuzzTarget: FuzzTarget = {
  name: 'catalog',
  seeds: (): FuzzSeed[] => [{ name: 'default-catalog.json', bytes: new Uint8Array(readFileSync('src/core/catalog/default-catalog.json')) }],
  run(input: Uint8Array): FuzzOutcome {
    const text = decoder.decode(input);
    let catalog: Catalog;
    try {
      catalog = parseCatalogText(text, 'catalog.json');
    } catch (error) {
      if (error instanceof CatalogError) return { kind: 'refused', message: error.message };
      throw error;
    }
    const problems = jsonAcceptedProblems(text, catalog);
    const r = catalog.rail;
    if (!(r.minLength <= r.defaultLength && r.defaultLength <= r.maxLength)) problems.push('rail default length outside min..max');
    return { kind: 'accepted', problems };
  },
};
