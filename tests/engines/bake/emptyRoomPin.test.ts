/**
 * Objects are additive (issue #10): a scene without objects (`objects` absent or empty) must bake
 * with exactly the shaders and passes of the baker before objects existed. Pinned here: the
 * SHA-256 of every shader source the bake compiles (captured at gl.shaderSource, so nothing the
 * bake compiles escapes) and per-surface checksums of its maps, all recorded from the code
 * before the objects work (commit 3d3c8bd). Same shaders + same inputs ⇒ same maps; the map
 * checksums (Σ of each map, and its largest texel) are compared to 1e-6 relative so the pin holds
 * on any GL back end, not only this machine's llvmpipe.
 */
import { createHash } from 'node:crypto';
import { writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { basePhotometry, isotropic, spot } from './bakeTestKit';
import { recordShaderSources } from './recordShaderSources';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const compiled = recordShaderSources(gl);
const baker = createBaker(gl);

const room: BakeScene['room'] = {
  width: 3,
  height: 2.4,
  depth: 2.2,
  reflectance: { floor: 0.3, ceiling: 0.85, north: [0.7, 0.5, 0.3], south: 0.6, west: 0.5, east: 0 },
};
const pendant = { ...spot(2000, 20, 10, 1), luminousOpening: { width: 0.2, length: 0.2, height: 0.1, shape: 'rectangular' as const } };
const luminaires: BakeScene['luminaires'] = [
  { photometry: pendant, position: [1.2, 2.0, 1.0], yaw: 15, pitch: 10, roll: 0 },
  { photometry: isotropic(150), position: [2.5, 1.0, 0.3], yaw: 0, pitch: 0, roll: 0, color: [1, 0.8, 0.6] },
  { photometry: basePhotometry({ verticalAngles: [0, 90, 180], candela: [[0, 0, 300]] }), position: [0.5, 2.3, 1.8], yaw: 0, pitch: 0, roll: 0 },
];
// The selection forced onto the GPU: unset it follows the renderer (the CPU on this llvmpipe, the
// GPU's passes elsewhere), and the pinned shader set must be the same on every back end.
const settings = { texelSize: 0.2, samples: 32, bounces: 2, samplesPerDraw: 16, brightSelection: 'gpu' as const };

const sha = (s: string) => createHash('sha256').update(s).digest('hex').slice(0, 16);

/**
 * Recorded at 3d3c8bd (before objects): sorted SHA-256 prefixes of the compiled shader sources.
 * One source changed since, deliberately, with the maps unchanged to the bit: the bright gather
 * (d277f253067d15e7 → eec5549dca83b451) now runs the one bright-patch loop both bright passes share
 * (shaders/brightPatchGather.glsl.ts), whose receiver cosine is max(cos θ_r, 0) instead of the empty
 * room's |cos θ_r| — equal on room surfaces, where every patch lies in front (issue #28).
 * Issue #34 changed the direct passes (5 sources): candela now comes from dense profile grids
 * (four fetches, no bin-table search; docs/baker.md "Profile table"). The map checksums below did
 * not move beyond their 1e-6 tolerance (worst 1.6e-7 relative), so they stay as recorded.
 * Issue #34 then moved the bright-patch selection onto the GPU (docs/baker.md "Bright patches
 * selected on the GPU"): six new passes (tile keys, block sums, top-k block and merge, patch table,
 * mask), the bright gather (9d936dc33d591134 → one of the new hashes: it stops at a table's
 * sentinel row) and the residual pass (eec5549dca83b451 → one of the new hashes: its mask is the
 * atlas, at an offset). The same tiles are taken; the rectangles are computed in float32 on the
 * GPU, and the checksums moved by at most 2.9e-7 relative, within the tolerance.
 */
const SHADERS = [
  '01baa4265d839960',
  '0f60c96f28184550',
  '1ad908f9e2dd7117',
  '28a3626c550b850b',
  '2a54593de58f3546',
  '2ac43edf303fe17e',
  '2ec6a6d30aa4a1d6',
  '34d6979c4db75101',
  '38b39ce0be018d75',
  '3bce97f088147e49',
  '3ce4092c26be7783',
  '5541ac5901f6fe22',
  '55d1f4d319b557d2',
  '6004a25e159cde27',
  '6bdeafb5d0119a64',
  '6f8ec08bc124a86f',
  '99d4fc4d46d1af2c',
  '9de21ee0f4e0551d',
  'a22e5be0a7dd81f4',
  'aa386da2ab6976d6',
  'b19e0774297d3ba4',
  'b1e956c5c41a7e88',
  'dbf7665cb8fb53bc',
  'e3d3056b459aafc0',
  'efe5f9b5bd2b432e',
  'f15cdd941093e784',
  'fe783aec8587b550',
];
/** Recorded at 3d3c8bd: per surface, [Σ direct, Σ indirect, Σ total, max total] over all RGB floats. */
const MAPS: Record<string, number[]> = {
  floor: [95499.2288, 37851.43682, 133350.6654, 658.6694336],
  ceiling: [62086.37255, 32413.40875, 94499.78132, 6164.246094],
  north: [50603.58721, 38488.33592, 89091.92336, 1387.742065],
  south: [10903.85614, 47368.45777, 58272.31385, 422.3456726],
  west: [6153.910726, 37924.1124, 44078.02314, 311.7947693],
  east: [28570.41549, 31899.41616, 60469.83198, 725.9751587],
};

function checksums(scene: BakeScene) {
  const { maps } = baker.bake(scene, settings);
  return Object.fromEntries(
    SURFACE_NAMES.map((n) => {
      const m = maps[n];
      const sum = (a: Float32Array) => a.reduce((s, x) => s + x, 0);
      return [n, [sum(m.direct), sum(m.indirect), sum(m.total), Math.max(...m.total)]];
    }),
  );
}

describe('a scene without objects bakes exactly as before objects existed', () => {
  it('objects absent: the same shader sources and the same maps', () => {
    const got = checksums({ room, luminaires });
    const shaders = [...new Set(compiled.map(sha))].sort();
    if (process.env.PIN_RECORD) writeFileSync(process.env.PIN_RECORD, JSON.stringify({ shaders, got }));
    expect(shaders).toEqual(SHADERS);
    for (const n of SURFACE_NAMES) {
      got[n].forEach((v, k) => expect(Math.abs(v - MAPS[n][k])).toBeLessThanOrEqual(1e-6 * Math.abs(MAPS[n][k]) + 1e-9));
    }
  });

  it('objects: [] compiles nothing new and gives the same maps', () => {
    const before = compiled.length;
    const got = checksums({ room, luminaires, objects: [] });
    // The program cache is keyed by source: an identical set of shaders compiles nothing.
    expect(compiled.length).toBe(before);
    for (const n of SURFACE_NAMES) {
      got[n].forEach((v, k) => expect(Math.abs(v - MAPS[n][k])).toBeLessThanOrEqual(1e-6 * Math.abs(MAPS[n][k]) + 1e-9));
    }
  });
});
