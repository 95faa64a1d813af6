import { describe, expect, it } from 'vitest';
import defaultCatalogData from '../../../src/core/catalog/default-catalog.json';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { InputError } from '../../../src/core/inputError';
import { EmbedOptionsError, resolveCatalog } from '../../../src/hosts/embed/resolveCatalog';

describe('resolveCatalog (embedding options)', () => {
  it('uses the bundled catalog by default and accepts a matching currency', () => {
    expect(resolveCatalog({}, defaultCatalog).id).toBe('luxbox-demo-rail');
    expect(resolveCatalog({ currency: 'EUR' }, defaultCatalog).currency).toBe('EUR');
  });

  it('refuses a currency the catalog is not priced in, naming both', () => {
    expect(() => resolveCatalog({ currency: 'CHF' }, defaultCatalog)).toThrow(EmbedOptionsError);
    expect(() => resolveCatalog({ currency: 'CHF' }, defaultCatalog)).toThrow("options.currency is CHF but the catalog's prices are in EUR");
  });

  it("takes a host's catalog and reports its bad fields under options.catalog", () => {
    const chf = { ...defaultCatalogData, id: 'shop-chf', currency: 'CHF' };
    expect(resolveCatalog({ catalog: chf, currency: 'CHF' }, defaultCatalog).id).toBe('shop-chf');
    const broken = { ...defaultCatalogData, rail: { ...defaultCatalogData.rail, maxLength: 3.05 } };
    expect(() => resolveCatalog({ catalog: broken }, defaultCatalog)).toThrow(InputError);
    expect(() => resolveCatalog({ catalog: broken }, defaultCatalog)).toThrow('options.catalog: rail.maxLength: must be a multiple of step 0.1');
  });

  it("uses the host's catalog without a bundled one (the package doors load that lazily), and refuses a mount with neither", () => {
    expect(resolveCatalog({ catalog: defaultCatalogData }, undefined).id).toBe('luxbox-demo-rail');
    expect(() => resolveCatalog({}, undefined)).toThrow(EmbedOptionsError);
    expect(() => resolveCatalog({}, undefined)).toThrow('options.catalog is missing and no bundled catalog was given');
  });
});
