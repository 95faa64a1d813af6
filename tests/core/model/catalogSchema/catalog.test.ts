import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import data from '../../../../src/core/catalog/default-catalog.json';
import { CatalogError, parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { parsePhotometry } from '../../../../src/core/photometry';
import { catalog } from '../helpers';

describe('default catalog', () => {
  it('has rails, straight, 90° and flexible connectors, ≥ 4 module types and ≥ 5 presets', () => {
    expect(catalog.rail).toMatchObject({ minLength: 0.5, maxLength: 3, step: 0.1 });
    expect(
      catalog.connectors
        .filter((c) => !c.flex && (c.ports ?? 2) === 2)
        .map((c) => c.angle)
        .sort(),
    ).toEqual([0, 90]);
    expect(catalog.connectors.find((c) => c.flex)?.flex).toEqual({ maxAngle: 90, step: 5 });
    expect(catalog.moduleTypes.length).toBeGreaterThanOrEqual(4);
    expect(catalog.presets.length).toBeGreaterThanOrEqual(5);
  });

  // Lumens and watts must be what the photometric file states (read by the independent photometry parser).
  for (const type of catalog.moduleTypes) {
    for (const beam of type.beams) {
      it(`${type.id}/${beam.id}: ${beam.photometry} states ${beam.lumens} lm, ${beam.watts} W`, () => {
        const p = parsePhotometry(readFileSync(`public/${beam.photometry}`), beam.photometry);
        expect(p.statedLumens).not.toBeNull();
        expect(Math.abs(p.statedLumens! - beam.lumens) / beam.lumens).toBeLessThan(0.005);
        expect(p.inputWatts).toBeCloseTo(beam.watts, 2);
      });
    }
  }
});

describe('parseCatalog errors name the field', () => {
  const broken = (mutate: (c: typeof data) => void) => {
    const c = structuredClone(data);
    mutate(c);
    return () => parseCatalog(c, 'my.json');
  };
  it('rejects an off-grid rail length', () => {
    expect(broken((c) => (c.rail.maxLength = 3.05))).toThrow(/my\.json: rail\.maxLength: must be a multiple of step 0\.1/);
  });
  it('rejects unknown references in presets', () => {
    expect(broken((c) => (c.presets[0].rails[0].modules[0].type = 'laser'))).toThrow(/presets\[0\]\.rails\[0\]\.modules\[0\]\.type: unknown module type 'laser'/);
    expect(broken((c) => (c.presets[2].joints[0].turn = 45))).toThrow(CatalogError);
  });
  it('rejects a default CCT that is not offered and a bad currency', () => {
    expect(broken((c) => (c.moduleTypes[0].defaultCct = 5000))).toThrow(/moduleTypes\[0\]\.defaultCct/);
    expect(broken((c) => (c.currency = 'euro'))).toThrow(/currency: must be an ISO 4217 code/);
  });
});
