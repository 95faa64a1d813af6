import { describe, expect, it } from 'vitest';
import { readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { intensity } from '../../src/core/photometry/intensity';
import { candelaAt } from '../../src/reference/candelaAt';
import { realPhotometry } from './photometryFixtures';

describe('reference candela lookup', () => {
  it('agrees with src/core/photometry intensity() on every real file (two independent bilinear lookups)', () => {
    const dir = fileURLToPath(new URL('../../public/ies/', import.meta.url));
    const files = readdirSync(dir).filter((f) => /\.(ies|ldt)$/i.test(f));
    expect(files.length).toBeGreaterThanOrEqual(30);
    // A fixed low-discrepancy set of directions (golden-ratio sequence), no RNG needed.
    const phi = (Math.sqrt(5) - 1) / 2;
    for (const f of files) {
      const ph = realPhotometry(f);
      let peak = 0;
      for (const row of ph.candela) for (const v of row) peak = Math.max(peak, v);
      for (let k = 0; k < 400; k++) {
        const gamma = ((k + 0.5) / 400) * 180;
        const c = ((k * phi) % 1) * 360;
        expect(Math.abs(candelaAt(ph, gamma, c) - intensity(ph, gamma, c))).toBeLessThanOrEqual(1e-9 * peak);
      }
      // Grid nodes are reproduced exactly.
      const h = ph.horizontalAngles.length - 1;
      const v = ph.verticalAngles.length >> 1;
      expect(candelaAt(ph, ph.verticalAngles[v], ph.horizontalAngles[h])).toBeCloseTo(ph.candela[h][v], 9);
    }
  });
});
