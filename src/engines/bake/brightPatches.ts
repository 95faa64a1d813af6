import type { Rgb, Vec3 } from '../../core/model/lightingScene';
import { brightGatherFragment, residualFragment, tileSumFragment } from '../../../shaders/brightPatch.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import { bindTexture, createDataTexture, createFloatTarget, deleteTarget, drawInto, readRgba, type FloatTarget } from './glResources';
import type { SurfaceLayout } from './surfaceLayout';

/**
 * "Bright patches": the first bounce from the small, very bright regions of
 * the direct maps, computed deterministically (docs/baker.md, "Bright
 * patches"). The direct maps are tiled; the tiles that carry the heavy tail of
 * the Monte Carlo gather (largest Σ M²·A, M = ρ·E the exitance) are taken out
 * of the maps the gather samples (the residual maps) and their light is
 * gathered exactly instead: each becomes a uniformly emitting rectangle with
 * the tile's flux, its flux centroid and its second moments, and every
 * receiving texel adds M·F(dA → rectangle) with Lambert's exact
 * point-to-polygon form factor. The bounce is linear in the direct maps, so
 * splitting them into residual + bright parts changes nothing but the noise;
 * the only approximation is replacing a tile's exitance distribution by the
 * moment-matched rectangle (the same order as the bilinear map lookup it
 * replaces, and exact in flux: Σ over the receivers = the tile's reflected flux).
 */

/** One bright tile as the gather sees it: a uniformly emitting rectangle on a room surface. */
export interface BrightPatch {
  surface: number;
  /** Tile indices on that surface. */
  tileU: number;
  tileV: number;
  /** Centre (world), half edges along the surface's u and v axes (metres). */
  centre: Vec3;
  halfU: number;
  halfV: number;
  /** Reflected flux ρ·Φ per channel, lm, and the exitance M = flux / area of the rectangle. */
  flux: Rgb;
  exitance: Rgb;
}

/** Per-tile sums of one surface, as the tile pass writes them (4 floats per tile in each array). */
export interface SurfaceTileSums {
  layout: SurfaceLayout;
  reflectance: Rgb;
  /** Texels per tile edge. */
  tile: number;
  tilesU: number;
  tilesV: number;
  /** (Σ E_r·a, Σ E_g·a, Σ E_b·a, Σ y²·a) per tile, y = Y(ρ·E). */
  sums: Float32Array;
  /** (Σ y·a·u, Σ y·a·v, Σ y·a·u², Σ y·a·v²), u, v from the tile corner, metres. */
  moments: Float32Array;
}

export interface BrightSelection {
  patches: BrightPatch[];
  /** Peakedness S·Σ M²A / (Σ M A)² of all exitance (1 = uniform), and the same with Σ M²A over only what the Monte Carlo gather still samples. */
  peakedness: number;
  residualPeakedness: number;
}

/**
 * Which tiles to gather deterministically. The variance of the cosine-sampled
 * gather of bounce 1 is, up to geometry, Σ M²·A over what it samples; for a
 * uniform exitance of the same flux it would be (Σ M·A)²/S. Tiles are taken in
 * decreasing Σ M²·A until the "peakedness" S·Σ M²A/(Σ MA)² of what the gather
 * still samples (Σ M²A over the residual, Σ MA over all exitance) is below
 * `targetPeakedness`, at most `maxPatches`, and only tiles whose mean exitance is
 * above `minContrast` × the room mean (a smooth room selects nothing and pays
 * nothing).
 */
export function selectBrightPatches(
  surfaces: SurfaceTileSums[],
  options: { maxPatches: number; targetPeakedness: number; minContrast: number },
): BrightSelection {
  interface Candidate {
    s: SurfaceTileSums;
    k: number;
    score: number;
    flux: Rgb;
    y: number;
  }
  // Totals first (no allocation per tile: a 20 m corridor has ~25 000 tiles), then
  // only the tiles bright enough to qualify become candidates and are sorted.
  let area = 0;
  let scoreAll = 0;
  let yAll = 0;
  const yOfTile = (s: SurfaceTileSums, k: number) =>
    LUMINANCE_WEIGHTS[0] * Math.max(0, s.sums[4 * k]) * s.reflectance[0] +
    LUMINANCE_WEIGHTS[1] * Math.max(0, s.sums[4 * k + 1]) * s.reflectance[1] +
    LUMINANCE_WEIGHTS[2] * Math.max(0, s.sums[4 * k + 2]) * s.reflectance[2];
  for (const s of surfaces) {
    area += s.layout.lengthU * s.layout.lengthV;
    for (let k = 0; k < s.tilesU * s.tilesV; k++) {
      const y = yOfTile(s, k);
      const score = Math.max(0, s.sums[4 * k + 3]);
      if (!(y > 0) || !Number.isFinite(y) || !Number.isFinite(score)) continue;
      scoreAll += score;
      yAll += y;
    }
  }
  const candidates: Candidate[] = [];
  const meanExitance = yAll / area;
  for (const s of surfaces) {
    const du = s.layout.lengthU / s.layout.width;
    const dv = s.layout.lengthV / s.layout.height;
    for (let k = 0; k < s.tilesU * s.tilesV; k++) {
      const y = yOfTile(s, k);
      const score = Math.max(0, s.sums[4 * k + 3]);
      // The tile's own area (the last row and column may be partial).
      const iu = k % s.tilesU;
      const iv = Math.floor(k / s.tilesU);
      const tileArea = (Math.min(s.layout.width, (iu + 1) * s.tile) - iu * s.tile) * du * (Math.min(s.layout.height, (iv + 1) * s.tile) - iv * s.tile) * dv;
      if (!(y >= options.minContrast * meanExitance * tileArea) || !Number.isFinite(y) || !Number.isFinite(score)) continue;
      const flux = [0, 1, 2].map((c) => Math.max(0, s.sums[4 * k + c]) * s.reflectance[c]) as Rgb;
      candidates.push({ s, k, score, flux, y });
    }
  }
  // Relative to all of the exitance: the residual's noise against the whole signal.
  const peak = (score: number) => (yAll > 0 ? (area * score) / (yAll * yAll) : 1);
  const peakedness = peak(scoreAll);
  const patches: BrightPatch[] = [];
  if (!(yAll > 0) || options.maxPatches <= 0) return { patches, peakedness, residualPeakedness: peakedness };
  candidates.sort((a, b) => b.score - a.score);
  let score = scoreAll;
  for (const c of candidates) {
    if (patches.length >= options.maxPatches || peak(score) <= options.targetPeakedness) break;
    const { layout, tile } = c.s;
    const du = layout.lengthU / layout.width;
    const dv = layout.lengthV / layout.height;
    const iu = c.k % c.s.tilesU;
    const iv = Math.floor(c.k / c.s.tilesU);
    // Tile extent (the last row/column may be partial).
    const u0 = iu * tile * du;
    const v0 = iv * tile * dv;
    const u1 = Math.min(layout.lengthU, (iu + 1) * tile * du);
    const v1 = Math.min(layout.lengthV, (iv + 1) * tile * dv);
    if (c.y / ((u1 - u0) * (v1 - v0)) < options.minContrast * meanExitance) continue;
    const m = c.s.moments.subarray(4 * c.k, 4 * c.k + 4);
    // Flux centroid and spread of the tile's exitance (plus the spread inside a texel).
    const mu = m[0] / c.y;
    const mv = m[1] / c.y;
    const varU = Math.max(0, m[2] / c.y - mu * mu) + (du * du) / 12;
    const varV = Math.max(0, m[3] / c.y - mv * mv) + (dv * dv) / 12;
    const cu = u0 + Math.min(Math.max(mu, 0), u1 - u0);
    const cv = v0 + Math.min(Math.max(mv, 0), v1 - v0);
    // A uniform rectangle with the same mean and variance has half edge √3·σ; keep it in the tile.
    const halfU = Math.max(1e-4, Math.min(Math.sqrt(3 * varU), cu - u0, u1 - cu));
    const halfV = Math.max(1e-4, Math.min(Math.sqrt(3 * varV), cv - v0, v1 - cv));
    const centre: Vec3 = [layout.origin[0], layout.origin[1], layout.origin[2]];
    centre[layout.uAxisIndex] = cu;
    centre[layout.vAxisIndex] = cv;
    const rectArea = 4 * halfU * halfV;
    patches.push({
      surface: layout.index,
      tileU: iu,
      tileV: iv,
      centre,
      halfU,
      halfV,
      flux: c.flux,
      exitance: c.flux.map((f) => f / rectArea) as Rgb,
    });
    score -= c.score;
  }
  return { patches, peakedness, residualPeakedness: peak(Math.max(0, score)) };
}

/** Texels per tile edge for a target tile size (metres). */
export function tileTexels(layout: SurfaceLayout, tileSize: number): number {
  const texel = Math.max(layout.lengthU / layout.width, layout.lengthV / layout.height);
  return Math.max(1, Math.round(tileSize / texel));
}

/** What the baker needs per surface: the map the Monte Carlo gather reads for bounce 1 and the exact bright-patch illuminance. */
export interface BrightPatchPass {
  selection: BrightSelection;
  /** Per surface index: the residual direct map (null: gather the direct map itself). */
  residual: (FloatTarget | null)[];
  /** Per surface index: E from the bright patches at texel centres (null when there are none). */
  bright: (FloatTarget | null)[];
  dispose(): void;
}

/**
 * Run the tile pass on the direct maps, select the bright patches, and build
 * the residual maps and the bright-patch illuminance per surface. `program`
 * compiles (or takes from the cache) a fragment shader; `countRead` is told
 * about the one read-back (the tile sums of all surfaces, a few kB: the
 * selection is made on the CPU).
 */
export function runBrightPatchPass(
  gl: WebGL2RenderingContext,
  linear: boolean,
  layouts: SurfaceLayout[],
  reflectance: Rgb[],
  direct: FloatTarget[],
  options: { maxPatches: number; tileSize: number; targetPeakedness: number; minContrast: number },
  program: (source: string, pass: string) => WebGLProgram,
  countRead: (bytes: number) => void = () => {},
  // Render targets: the baker's pool (targetPool.ts: allocating RGBA32F targets per bake is slow on a GPU); by default new ones.
  targets: { acquire(width: number, height: number, zero?: boolean): FloatTarget; release(target: FloatTarget): void } = {
    acquire: (width, height) => createFloatTarget(gl, width, height, linear),
    release: (target) => deleteTarget(gl, target),
  },
): BrightPatchPass {
  const none: BrightPatchPass = {
    selection: { patches: [], peakedness: 1, residualPeakedness: 1 },
    residual: layouts.map(() => null),
    bright: layouts.map(() => null),
    dispose() {},
  };
  if (options.maxPatches <= 0) return none;
  const reflecting = layouts.filter((l) => reflectance[l.index].some((r) => r > 0));
  if (reflecting.length === 0) return none;
  const tileProg = program(tileSumFragment, 'bright tiles');
  // Every surface's tile sums (mode 0) and moments (mode 1) side by side in one
  // atlas target, so the whole selection costs one read-back.
  const grids = reflecting.map((layout) => {
    const tile = tileTexels(layout, options.tileSize);
    return { layout, tile, tilesU: Math.ceil(layout.width / tile), tilesV: Math.ceil(layout.height / tile) };
  });
  const atlasWidth = grids.reduce((w, g) => w + g.tilesU, 0);
  const rowsPerMode = Math.max(...grids.map((g) => g.tilesV));
  // Every texel that is read back below is written first: no clear needed.
  const atlas = targets.acquire(atlasWidth, 2 * rowsPerMode, false);
  let x0 = 0;
  const offsets = grids.map((g) => {
    const x = x0;
    x0 += g.tilesU;
    for (const mode of [0, 1]) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, atlas.framebuffer);
      gl.viewport(x, mode * rowsPerMode, g.tilesU, g.tilesV);
      gl.useProgram(tileProg);
      bindTexture(gl, tileProg, 'uMap', 0, direct[g.layout.index].texture);
      gl.uniform2i(gl.getUniformLocation(tileProg, 'uOffset'), x, mode * rowsPerMode);
      gl.uniform1i(gl.getUniformLocation(tileProg, 'uTile'), g.tile);
      gl.uniform1i(gl.getUniformLocation(tileProg, 'uMode'), mode);
      gl.uniform2f(gl.getUniformLocation(tileProg, 'uTexel'), g.layout.lengthU / g.layout.width, g.layout.lengthV / g.layout.height);
      gl.uniform3fv(gl.getUniformLocation(tileProg, 'uRho'), reflectance[g.layout.index]);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    return x;
  });
  const all = readRgba(gl, atlas);
  countRead(all.byteLength);
  targets.release(atlas);
  const sums: SurfaceTileSums[] = grids.map((g, k) => {
    const cut = (mode: number) => {
      const out = new Float32Array(g.tilesU * g.tilesV * 4);
      for (let j = 0; j < g.tilesV; j++) {
        const from = ((mode * rowsPerMode + j) * atlasWidth + offsets[k]) * 4;
        out.set(all.subarray(from, from + g.tilesU * 4), j * g.tilesU * 4);
      }
      return out;
    };
    return { ...g, reflectance: reflectance[g.layout.index], sums: cut(0), moments: cut(1) };
  });
  const selection = selectBrightPatches(sums, options);
  if (selection.patches.length === 0) return { ...none, selection };

  // Patch table: 4 RGBA texels per patch (centre + surface, half edge u, half edge v, exitance).
  const n = selection.patches.length;
  const data = new Float32Array(n * 16);
  selection.patches.forEach((p, k) => {
    const layout = layouts[p.surface];
    const hu: Vec3 = [0, 0, 0];
    hu[layout.uAxisIndex] = p.halfU;
    const hv: Vec3 = [0, 0, 0];
    hv[layout.vAxisIndex] = p.halfV;
    data.set([...p.centre, p.surface, ...hu, 0, ...hv, 0, ...p.exitance, 0], 16 * k);
  });
  const patchTexture = createDataTexture(gl, data, 4, n, 4);
  const made: FloatTarget[] = [];
  const textures: WebGLTexture[] = [patchTexture];

  // Residual maps: the bright tiles cut out of the direct maps they lie on.
  const residual = layouts.map((layout): FloatTarget | null => {
    const own = selection.patches.filter((p) => p.surface === layout.index);
    if (own.length === 0) return null;
    const s = sums.find((x) => x.layout.index === layout.index)!;
    const mask = new Float32Array(s.tilesU * s.tilesV * 4);
    for (const p of own) mask[4 * (p.tileV * s.tilesU + p.tileU)] = 1;
    const maskTexture = createDataTexture(gl, mask, s.tilesU, s.tilesV, 4);
    textures.push(maskTexture);
    const prog = program(residualFragment, 'bright residual');
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    drawInto(gl, out, prog, () => {
      bindTexture(gl, prog, 'uMap', 0, direct[layout.index].texture);
      bindTexture(gl, prog, 'uMask', 1, maskTexture);
      gl.uniform1i(gl.getUniformLocation(prog, 'uTile'), s.tile);
    });
    return out;
  });

  // Exact gather from the bright patches at every texel centre of every surface.
  const gatherProg = program(brightGatherFragment, 'bright gather');
  const bright = layouts.map((layout): FloatTarget | null => {
    if (selection.patches.every((p) => p.surface === layout.index)) return null;
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    const axisU: Vec3 = [0, 0, 0];
    axisU[layout.uAxisIndex] = layout.lengthU;
    const axisV: Vec3 = [0, 0, 0];
    axisV[layout.vAxisIndex] = layout.lengthV;
    drawInto(gl, out, gatherProg, () => {
      bindTexture(gl, gatherProg, 'uPatches', 0, patchTexture);
      gl.uniform1i(gl.getUniformLocation(gatherProg, 'uPatchCount'), n);
      gl.uniform3fv(gl.getUniformLocation(gatherProg, 'uOrigin'), layout.origin);
      gl.uniform3fv(gl.getUniformLocation(gatherProg, 'uAxisU'), axisU);
      gl.uniform3fv(gl.getUniformLocation(gatherProg, 'uAxisV'), axisV);
      gl.uniform3fv(gl.getUniformLocation(gatherProg, 'uNormal'), layout.normal);
      gl.uniform2f(gl.getUniformLocation(gatherProg, 'uResolution'), layout.width, layout.height);
      gl.uniform1i(gl.getUniformLocation(gatherProg, 'uSurface'), layout.index);
    });
    return out;
  });

  return {
    selection,
    residual,
    bright,
    dispose() {
      for (const t of made) targets.release(t);
      for (const t of textures) gl.deleteTexture(t);
    },
  };
}

/** Tile size of the bright-patch search, metres (about the reference's patch size; at least one texel). */
export const BRIGHT_TILE_SIZE = 0.1;

/** The pass's options for given bake settings. */
export function brightPatchOptions(settings: { brightPatches: number }): { maxPatches: number; tileSize: number; targetPeakedness: number; minContrast: number } {
  return { maxPatches: settings.brightPatches, tileSize: BRIGHT_TILE_SIZE, targetPeakedness: 1, minContrast: 3 };
}

/** Summary for the bake report. */
export function brightPatchReport(selection: BrightSelection): { count: number; peakedness: number; residualPeakedness: number } {
  return { count: selection.patches.length, peakedness: selection.peakedness, residualPeakedness: selection.residualPeakedness };
}
