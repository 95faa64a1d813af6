/**
 * GPU baker with objects (issue #10) against the independent CPU reference for furnished
 * rooms (src/reference/solveFurnishedReference.ts: its own BVH and shadow rays, radiosity on
 * wall rectangles and object triangles, a final gather at the query point; it shares no code
 * with src/engines/bake, the shaders or three-mesh-bvh). Compared per texel, on the walls at
 * texel centres and on the object atlas at the G-buffer's sample points and normals, for
 * direct and total light, and as flux Σ E·A over the walls and over the objects.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type LightingScene, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { Photometry } from '../../../src/core/photometry/types';
import type { BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { texelArea, texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { furnishedIlluminanceAt } from '../../../src/reference/furnishedIlluminanceAt';
import { luminanceAt, solveFurnishedReference, type FurnishedResult } from '../../../src/reference/solveFurnishedReference';
import { closestHit } from '../../../src/reference/triangleBvh';
import { boxMesh, tableMesh } from '../../reference/meshFixtures';
import { loadIes } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);

/** Source-cell size of both models (the baker's sourceSpacing, the reference's openingCell). */
const CELL = 0.05;
/** Texel centres (no supersampling), so direct light compares point by point with the reference's exact point values. */
const SETTINGS = { texelSize: 0.1, samples: 128, bounces: 5, sourceSpacing: CELL, texelSupersampling: 1 };

interface Pair {
  bake: number;
  reference: number;
}

interface Comparison {
  walls: { direct: Pair[]; total: Pair[] };
  atlas: { direct: Pair[]; total: Pair[] };
  /** Texels facing another surface closer than SLOT (wall and object, both sides of a gap), apart from the rest. */
  slot: { total: Pair[] };
  flux: { walls: { direct: Pair; total: Pair }; objects: { direct: Pair; total: Pair } };
  reference: FurnishedResult;
}

/** RMS and largest relative error over pairs whose reference exceeds `floor`. */
function errors(pairs: Pair[], floor: number): { n: number; rms: number; max: number } {
  const e = pairs.filter((p) => p.reference > floor).map((p) => Math.abs(p.bake / p.reference - 1));
  return { n: e.length, rms: e.length ? Math.sqrt(e.reduce((s, x) => s + x * x, 0) / e.length) : 0, max: e.length ? Math.max(...e) : 0 };
}

const rel = (p: Pair): number => p.bake / p.reference - 1;

/**
 * A narrow gap: the cabinet stands 1 cm from the wall. There the reference's indirect light is
 * constant over a 25 cm patch that is half in the gap and half outside (its direct light is
 * resolved per 6 cm piece), so it overestimates light in the gap; such texels are reported
 * apart, not in the RMS.
 */
const SLOT = 0.02;

/** Distance from p along n to the room's box or to an object (the reference's own BVH), up to SLOT. */
function facesGap(reference: FurnishedResult, p: Vec3, n: Vec3): boolean {
  let t = Infinity;
  for (let a = 0; a < 3; a++) {
    if (n[a] > 1e-9) t = Math.min(t, (reference.extent[a] - p[a]) / n[a]);
    else if (n[a] < -1e-9) t = Math.min(t, -p[a] / n[a]);
  }
  if (t < SLOT) return true;
  if (!reference.occluders) return false;
  const o = [p[0] + 1e-5 * n[0], p[1] + 1e-5 * n[1], p[2] + 1e-5 * n[2]];
  return closestHit(reference.occluders.bvh, o, n, 0, SLOT).t < SLOT;
}

function compare(scene: LightingScene, files: Record<string, Photometry>, objects: BakeObject[], referencePatch: number, stride: number): Comparison {
  const bakeScene: BakeScene = {
    room: scene.room,
    luminaires: scene.luminaires.map((l) => ({ ...l, photometry: files[l.photometry] })),
    objects,
  };
  const { maps } = baker.bake(bakeScene, SETTINGS);
  const reference = solveFurnishedReference(scene, files, objects, { patchSize: referencePatch, openingCell: CELL });
  const out: Comparison = {
    walls: { direct: [], total: [] },
    atlas: { direct: [], total: [] },
    slot: { total: [] },
    flux: fluxes(maps, reference),
    reference,
  };
  for (const name of SURFACE_NAMES) {
    const m = maps[name];
    const [direct, total] = [luxOf(m.direct), luxOf(m.total)];
    for (let j = 1; j < m.layout.height; j += stride) {
      for (let i = 1; i < m.layout.width; i += stride) {
        const k = j * m.layout.width + i;
        const p = texelCentre(m.layout, i, j);
        const r = furnishedIlluminanceAt(reference, p, m.layout.normal);
        out.walls.direct.push({ bake: direct[k], reference: r.direct });
        if (facesGap(reference, p, m.layout.normal)) out.slot.total.push({ bake: total[k], reference: r.total });
        else out.walls.total.push({ bake: total[k], reference: r.total });
      }
    }
  }
  const o = maps.objects;
  if (!o) throw new Error('the bake of a furnished scene has no object maps');
  const [direct, total] = [luxOf(o.direct), luxOf(o.total)];
  const { position, normal } = o.atlas;
  for (let k = 0; k < o.atlas.width * o.atlas.height; k++) {
    // Fully covered texels: their sample point is the texel centre on the chart.
    if (position[4 * k + 3] < 0.999) continue;
    const p: Vec3 = [position[4 * k], position[4 * k + 1], position[4 * k + 2]];
    const n: Vec3 = [normal[4 * k], normal[4 * k + 1], normal[4 * k + 2]];
    const r = furnishedIlluminanceAt(reference, p, n);
    out.atlas.direct.push({ bake: direct[k], reference: r.direct });
    if (facesGap(reference, p, n)) out.slot.total.push({ bake: total[k], reference: r.total });
    else out.atlas.total.push({ bake: total[k], reference: r.total });
  }
  return out;
}

/** Σ E·A of the bake (walls: texels; objects: coverage · texel²) and of the reference (patch means · patch areas). */
function fluxes(maps: BakedMaps, reference: FurnishedResult): Comparison['flux'] {
  const sum = { walls: { direct: 0, total: 0 }, objects: { direct: 0, total: 0 } };
  for (const name of SURFACE_NAMES) {
    const m = maps[name];
    const a = texelArea(m.layout);
    for (const e of luxOf(m.direct)) sum.walls.direct += e * a;
    for (const e of luxOf(m.total)) sum.walls.total += e * a;
  }
  const o = maps.objects;
  if (o) {
    const t2 = o.atlas.texelSize * o.atlas.texelSize;
    const [d, t] = [luxOf(o.direct), luxOf(o.total)];
    for (let k = 0; k < d.length; k++) {
      const c = o.atlas.position[4 * k + 3] * t2;
      sum.objects.direct += d[k] * c;
      sum.objects.total += t[k] * c;
    }
  }
  const ref = { walls: { direct: 0, total: 0 }, objects: { direct: 0, total: 0 } };
  reference.patches.forEach((p, i) => {
    const d = luminanceAt(reference.directRgb, 3 * i);
    const where = p.kind === 'wall' ? ref.walls : ref.objects;
    where.direct += p.area * d;
    where.total += p.area * (d + luminanceAt(reference.indirectRgb, 3 * i));
  });
  return {
    walls: { direct: { bake: sum.walls.direct, reference: ref.walls.direct }, total: { bake: sum.walls.total, reference: ref.walls.total } },
    objects: { direct: { bake: sum.objects.direct, reference: ref.objects.direct }, total: { bake: sum.objects.total, reference: ref.objects.total } },
  };
}

type Stats = ReturnType<typeof errors>;

function report(name: string, c: Comparison): { wallsDirect: Stats; wallsTotal: Stats; atlasDirect: Stats; atlasTotal: Stats; slotTotal: Stats } {
  const peak = Math.max(...c.walls.total.map((p) => p.reference), ...c.atlas.total.map((p) => p.reference));
  const r = {
    wallsDirect: errors(c.walls.direct, 0.01 * peak),
    wallsTotal: errors(c.walls.total, 0.01 * peak),
    atlasDirect: errors(c.atlas.direct, 0.01 * peak),
    atlasTotal: errors(c.atlas.total, 0.01 * peak),
    slotTotal: errors(c.slot.total, 0.01 * peak),
  };
  const pct = (x: number) => `${(100 * x).toFixed(2)} %`;
  console.info(
    `${name}: reference ${c.reference.patches.length} patches, ${c.reference.sweeps} sweeps (residual ${c.reference.residual.toExponential(1)}); ` +
      `walls direct RMS ${pct(r.wallsDirect.rms)} (n ${r.wallsDirect.n}), total RMS ${pct(r.wallsTotal.rms)} max ${pct(r.wallsTotal.max)}; ` +
      `atlas direct RMS ${pct(r.atlasDirect.rms)} (n ${r.atlasDirect.n}), total RMS ${pct(r.atlasTotal.rms)} max ${pct(r.atlasTotal.max)}; ` +
      `gap texels ${r.slotTotal.n}: total RMS ${pct(r.slotTotal.rms)}; ` +
      `flux walls direct ${pct(rel(c.flux.walls.direct))} total ${pct(rel(c.flux.walls.total))}, objects direct ${pct(rel(c.flux.objects.direct))} total ${pct(rel(c.flux.objects.total))}`,
  );
  return r;
}

const room = (w: number, h: number, d: number): LightingScene['room'] => ({
  width: w,
  height: h,
  depth: d,
  reflectance: { floor: 0.3, ceiling: 0.8, north: 0.6, south: 0.5, west: 0.6, east: 0.5 },
});

describe('GPU bake with objects vs the furnished CPU reference', () => {
  it('living room: a table and a cabinet under two downlights', () => {
    const scene: LightingScene = {
      version: 1,
      room: room(4, 2.6, 3),
      luminaires: [
        { photometry: 'down', position: [1.6, 2.55, 1.4], yaw: 0, pitch: 0, roll: 0 },
        { photometry: 'down', position: [3, 2.55, 2.2], yaw: 0, pitch: 0, roll: 0 },
      ],
    };
    const objects: BakeObject[] = [
      { id: 'table', mesh: tableMesh(1.4, 0.9, 0.75, 0.04, 0.06, [0.45, 0.35, 0.25]), position: [1.8, 0, 1.5], yaw: 10, scale: 1 },
      { id: 'cabinet', mesh: boxMesh([-0.5, 0, -0.2], [0.5, 0.9, 0.2], [0.7, 0.7, 0.7]), position: [3.2, 0, 0.21], yaw: 0, scale: 1 },
    ];
    const c = compare(scene, { down: loadIes('bega_50975_downlight_lm1995_crlf.ies') }, objects, 0.25, 3);
    const r = report('table + cabinet', c);
    // Measured: direct RMS 0.03 % walls, 0.01 % atlas; total RMS 2.2 % walls (worst texel 25 %), 3.2 % atlas
    // (worst 20 %); flux within 0.15 %. The 9 texels of the 1 cm gap behind the cabinet differ by ~86 % (see SLOT).
    expect(r.wallsDirect.rms).toBeLessThan(0.005);
    expect(r.atlasDirect.rms).toBeLessThan(0.005);
    expect(r.wallsTotal.rms).toBeLessThan(0.03);
    expect(r.atlasTotal.rms).toBeLessThan(0.05);
    expect(r.slotTotal.n).toBeLessThan(20);
    for (const f of [c.flux.walls.direct, c.flux.walls.total, c.flux.objects.direct, c.flux.objects.total]) expect(Math.abs(rel(f))).toBeLessThan(0.01);
  });

  it('stiff: a pendant 40 cm above a dining table', () => {
    const scene: LightingScene = {
      version: 1,
      room: room(4, 2.7, 3.5),
      luminaires: [{ photometry: 'pendant', position: [2, 1.15, 1.75], yaw: 0, pitch: 0, roll: 0 }],
    };
    const objects: BakeObject[] = [{ id: 'dining', mesh: tableMesh(1.6, 0.9, 0.75, 0.04, 0.06, [0.5, 0.5, 0.5]), position: [2, 0, 1.75], yaw: 0, scale: 1 }];
    const c = compare(scene, { pendant: loadIes('ledalite_pendant_direct_indirect_iesna95.ies') }, objects, 0.25, 3);
    const r = report('pendant over dining table', c);
    // Measured: direct RMS 0.02 % walls, 0.03 % table; total RMS 1.1 % walls (worst 9.5 %), 2.5 % table
    // (worst 16 %); flux within 0.4 %.
    expect(r.wallsDirect.rms).toBeLessThan(0.005);
    expect(r.atlasDirect.rms).toBeLessThan(0.005);
    expect(r.wallsTotal.rms).toBeLessThan(0.03);
    expect(r.atlasTotal.rms).toBeLessThan(0.05);
    expect(r.slotTotal.n).toBe(0);
    for (const f of [c.flux.walls.direct, c.flux.walls.total, c.flux.objects.direct, c.flux.objects.total]) expect(Math.abs(rel(f))).toBeLessThan(0.01);
  });
});
