/**
 * The module-count benchmark's scene (issue #15, docs/benchmarks.md "3D lifecycle"): an empty
 * 8 × 6 × 2.8 m room and `count` modules with the default catalog's real photometry
 * (public/ies), hung 0.6 m under the ceiling (the catalog's default suspension) on a grid of
 * rails: rows 1.2 m apart, five modules 1.3 m apart per row, filled row by row. The module
 * types cycle through spot, flood, linear, washer and direct/indirect, so every module is its
 * own group (its own position) and the mix is what a shopper configures. Deterministic.
 */
import { readFileSync } from 'node:fs';
import { defaultCatalog } from '../../src/core/catalog/defaultCatalog';
import { parsePhotometry } from '../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../src/core/photometry/types';
import type { BakeScene } from '../../src/engines/bake/bakeScene';
import { PUBLIC_DIR } from '../../src/hosts/node/renderInput';

export const MODULE_COUNT_ROOM = { width: 8, height: 2.8, depth: 6, reflectance: { floor: 0.3, ceiling: 0.8, north: 0.6, south: 0.6, west: 0.6, east: 0.6 } } as const;

/** Module types cycled over the grid (first beam of each type). */
const CYCLE = ['spot', 'flood', 'linear', 'washer', 'updown'] as const;
const PER_ROW = 5;

const parsed = new Map<string, Photometry>();
function photometry(path: string): Photometry {
  let p = parsed.get(path);
  if (!p) {
    p = parsePhotometry(readFileSync(PUBLIC_DIR + path), path);
    parsed.set(path, p);
  }
  return p;
}

export function moduleCountScene(count: number): BakeScene {
  if (!Number.isInteger(count) || count < 1 || count > 20) throw new Error(`module count ${count} is not an integer in 1..20`);
  const luminaires: BakeScene['luminaires'] = [];
  for (let i = 0; i < count; i++) {
    const typeId = CYCLE[i % CYCLE.length];
    const type = defaultCatalog.moduleTypes.find((t) => t.id === typeId);
    if (!type) throw new Error(`the default catalog has no module type ${typeId}`);
    const beam = type.beams[0];
    const row = Math.floor(i / PER_ROW);
    const col = i % PER_ROW;
    luminaires.push({
      photometry: photometry(beam.photometry),
      position: [1.4 + 1.3 * col, MODULE_COUNT_ROOM.height - 0.6, 1.2 + 1.2 * row],
      yaw: 90,
      pitch: 0,
      roll: beam.roll,
      dimming: 1,
      color: [1, 1, 1],
    });
  }
  return { room: { ...MODULE_COUNT_ROOM, reflectance: { ...MODULE_COUNT_ROOM.reflectance } }, luminaires };
}
