import { describe, expect, it } from 'vitest';
import defaultCatalogData from '../../../src/core/catalog/default-catalog.json';
import { InputError } from '../../../src/core/inputError';
import { EmbedOptionsError, resolveCatalog } from '../../../src/hosts/embed/resolveCatalog';

describe('resolveCatalog (embedding options)', () => {
  it('uses the bundled catalog by default and accepts a matching currency', () => {
    expect(resolveCatalog({}).id).toBe('luxbox-demo-rail');
    expect(resolveCatalog({ currency: 'EUR' }).currency).toBe('EUR');
  });

  it('refuses a currency the catalog is not priced in, naming both', () => {
    expect(() => resolveCatalog({ currency: 'CHF' })).toThrow(EmbedOptionsError);
    expect(() => resolveCatalog({ currency: 'CHF' })).toThrow("options.currency is CHF but the catalog's prices are in EUR");
  });

  it("takes a host's catalog and reports its bad fields under options.catalog", () => {
    const chf = { ...defaultCatalogData, id: 'shop-chf', currency: 'CHF' };
    expect(resolveCatalog({ catalog: chf, currency: 'CHF' }).id).toBe('shop-chf');
    const broken = { ...defaultCatalogData, rail: { ...defaultCatalogData.rail, maxLength: 3.05 } };
    expect(() => resolveCatalog({ catalog: broken })).toThrow(InputError);
    expect(() => resolveCatalog({ catalog: broken })).toThrow('options.catalog: rail.maxLength: must be a multiple of step 0.1');
  });
});
