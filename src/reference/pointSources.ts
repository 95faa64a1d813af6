import type { LightingLuminaire, LightingScene, Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import type { Photometry } from '../core/photometry/types';
import { tiltMultiplier } from '../core/photometry/tilt';
import { apply, luminaireToWorld, worldToLuminaire, type Mat3 } from './luminaireRotation';
import { ReferenceInputError } from './referenceInputError';

/** One photometric point source: a whole luminaire, or one cell of a discretised luminous opening. */
export interface ReferencePointSource {
  position: Vec3;
  /** world → luminaire-local rotation. */
  toLocal: Mat3;
  photometry: Photometry;
  /** Per-channel factor on the tabulated candela: dimming × colour ÷ number of cells. */
  scale: Rgb;
  /** Index of the luminaire in the scene. */
  luminaire: number;
  /**
   * Which directions this source emits, by the sign of their luminaire-local y:
   * −1 downward only (bottom face of a tall opening), +1 upward only (top face),
   * 0 all. See `openingCell`.
   */
  hemisphere: -1 | 0 | 1;
}

export interface PointSourceOptions {
  /**
   * Largest cell of a discretised luminous opening, metres. A luminaire whose opening
   * (Photometry.luminousOpening width along local x, length along local z) exceeds
   * it is split into a grid of equal cells, each a point source at its centre with
   * 1/n of the intensity: the far-field distribution applied to each part, as the
   * configurator paper and commercial tools do for near-field effects. An opening taller
   * than a cell (cylinders, boxes: they emit from sides and top) has the grid at its
   * bottom face (local y = −height/2) for the downward hemisphere and at its top
   * face (+height/2) for the upward one, each with the full distribution of its
   * hemisphere; a face is kept at least 1 cm inside the room (a luminaire mounted
   * closer to a wall than half its height). 0 disables it.
   * Default 0.05 m, the baker's default too (docs/baker.md), so both solve the
   * same physical model.
   */
  openingCell?: number;
  /** At most this many cells along each side of an opening (default 8). */
  maxCellsPerAxis?: number;
}

export const DEFAULT_OPENING_CELL = 0.05;
export const DEFAULT_MAX_CELLS_PER_AXIS = 8;

function cellsAlong(size: number, cell: number, max: number): number {
  if (!(cell > 0) || !(size > cell)) return 1;
  return Math.min(max, Math.ceil(size / cell - 1e-9));
}

/**
 * Expands the luminaires of a scene into point sources, validating what the
 * reference relies on. `photometries` maps the scene's `photometry` strings to
 * parsed data. Per luminaire: its inputs checked, the cells of its opening
 * (openingOffsets), the faces they sit on (openingFaces), one source per cell and face.
 */
export function referencePointSources(scene: LightingScene, photometries: ReadonlyMap<string, Photometry> | Record<string, Photometry>, options: PointSourceOptions = {}): ReferencePointSource[] {
  const lookup = (key: string): Photometry | undefined => (photometries instanceof Map ? photometries.get(key) : (photometries as Record<string, Photometry>)[key]);
  const { cell, maxCells } = checkedOptions(options);
  const { width, height, depth } = scene.room;
  const extent: Vec3 = [width, height, depth];
  const sources: ReferencePointSource[] = [];
  scene.luminaires.forEach((lum, index) => {
    const { ph, dimming, color } = checkedLuminaire(lum, index, extent, lookup);
    const toWorld = luminaireToWorld(lum.yaw, lum.pitch, lum.roll);
    const toLocal = worldToLuminaire(lum.yaw, lum.pitch, lum.roll);
    const offsets = openingOffsets(ph.luminousOpening, cell, maxCells);
    // TILT data scales the grid for a pitched lamp (LM-63-2002 §5.11; see tiltMultiplier).
    const share = (dimming * tiltMultiplier(ph, lum.pitch)) / offsets.length;
    for (const [y, hemisphere] of openingFaces(lum.position, toWorld, ph.luminousOpening, cell, extent)) {
      for (const off of offsets) {
        const o = apply(toWorld, [off[0], y, off[2]]);
        // Cells of an opening touching a wall could poke through it; keep them inside.
        const position = lum.position.map((c, a) => Math.min(Math.max(c + o[a], 0), extent[a])) as Vec3;
        sources.push({ position, toLocal, photometry: ph, scale: [share * color[0], share * color[1], share * color[2]], luminaire: index, hemisphere });
      }
    }
  });
  return sources;
}

function checkedOptions(options: PointSourceOptions): { cell: number; maxCells: number } {
  const cell = options.openingCell ?? DEFAULT_OPENING_CELL;
  if (!Number.isFinite(cell) || cell < 0) {
    throw new ReferenceInputError(`reference options: openingCell must be a finite number ≥ 0, got ${cell}`);
  }
  const maxCells = options.maxCellsPerAxis ?? DEFAULT_MAX_CELLS_PER_AXIS;
  if (!Number.isInteger(maxCells) || maxCells < 1) {
    throw new ReferenceInputError(`reference options: maxCellsPerAxis must be an integer ≥ 1, got ${maxCells}`);
  }
  return { cell, maxCells };
}

/** A luminaire's photometry, position (inside the room), angles, dimming and colour, each checked. */
function checkedLuminaire(lum: LightingLuminaire, index: number, extent: Vec3, lookup: (key: string) => Photometry | undefined): { ph: Photometry; dimming: number; color: Rgb } {
  const where = `luminaires[${index}]`;
  const ph = lookup(lum.photometry);
  if (!ph) throw new ReferenceInputError(`${where}.photometry: no photometry loaded for "${lum.photometry}"`);
  if (!Array.isArray(lum.position) || lum.position.length !== 3 || !lum.position.every(Number.isFinite)) {
    throw new ReferenceInputError(`${where}.position: expected three finite numbers`);
  }
  lum.position.forEach((c, a) => {
    if (c < 0 || c > extent[a]) {
      throw new ReferenceInputError(`${where}.position: [${lum.position.join(', ')}] lies outside the room (0..${extent[a]} m along ${'xyz'[a]})`);
    }
  });
  for (const key of ['yaw', 'pitch', 'roll'] as const) {
    if (!Number.isFinite(lum[key])) throw new ReferenceInputError(`${where}.${key}: expected a finite angle in degrees`);
  }
  const dimming = lum.dimming ?? 1;
  if (!Number.isFinite(dimming) || dimming < 0) throw new ReferenceInputError(`${where}.dimming: expected a finite number ≥ 0`);
  const color = lum.color ?? [1, 1, 1];
  if (color.length !== 3 || !color.every((c) => Number.isFinite(c) && c >= 0)) {
    throw new ReferenceInputError(`${where}.color: expected three finite numbers ≥ 0`);
  }
  return { ph, dimming, color };
}

/** The cell centres of an opening in its own plane (local x along its width, z along its length); one at the centre when it is not split. */
function openingOffsets(open: Photometry['luminousOpening'] | undefined, cell: number, maxCells: number): Vec3[] {
  const w = Math.abs(open?.width ?? 0);
  const l = Math.abs(open?.length ?? 0);
  const nx = cellsAlong(w, cell, maxCells);
  const nz = cellsAlong(l, cell, maxCells);
  // A disc, a vertical cylinder and a sphere all look round from below.
  const round = ['circular', 'elliptical', 'cylindrical', 'spherical'].includes(open?.shape ?? 'point');
  const offsets: Vec3[] = [];
  for (let i = 0; i < nx; i++) {
    for (let k = 0; k < nz; k++) {
      const x = nx > 1 ? ((i + 0.5) / nx - 0.5) * w : 0;
      const z = nz > 1 ? ((k + 0.5) / nz - 0.5) * l : 0;
      // Round openings keep the cells whose centre lies inside the ellipse.
      if (round && w > 0 && l > 0 && ((2 * x) / w) ** 2 + ((2 * z) / l) ** 2 > 1) continue;
      offsets.push([x, 0, z]);
    }
  }
  if (offsets.length === 0) offsets.push([0, 0, 0]);
  return offsets;
}

/**
 * The faces the cells sit on, as (local y, hemisphere): a tall opening has the grid at its bottom
 * face for light going down and at its top face for light going up; any other, one face at the
 * centre for all directions.
 */
function openingFaces(position: Vec3, toWorld: Mat3, open: Photometry['luminousOpening'] | undefined, cell: number, extent: Vec3): [number, -1 | 0 | 1][] {
  const tall = cell > 0 && Math.abs(open?.height ?? 0) > cell;
  if (!tall) return [[0, 0]];
  const half = 0.5 * Math.abs(open?.height ?? 0);
  // Each face stays ≥ 1 cm inside the room: the distance to the box along the luminaire's ±y axis.
  const axisY = apply(toWorld, [0, 1, 0]);
  const room = (dir: number): number => {
    let t = Infinity;
    for (let a = 0; a < 3; a++) {
      const v = dir * axisY[a];
      if (v > 1e-12) t = Math.min(t, (extent[a] - position[a]) / v);
      else if (v < -1e-12) t = Math.min(t, position[a] / -v);
    }
    return Math.min(half, Math.max(0, t - 0.01));
  };
  return [
    [-room(-1), -1],
    [room(1), 1],
  ];
}
