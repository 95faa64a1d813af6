import type { NearField, Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import { tiltMultiplier } from '../../core/photometry/tilt';
import type { BakeScene } from './bakeScene';
import { applyMat3, luminaireRotation, type Mat3 } from './luminaireRotation';
import { openingSources } from './pointSources';

/** One luminaire as point sources in the world: what the direct pass (GPU) and directAtPoint (CPU) both evaluate. */
export interface LampSources {
  /** Index of the luminaire in the scene. */
  luminaire: number;
  photometry: Photometry;
  /** Luminaire → world rotation. */
  rotation: Mat3;
  /** World positions of its point sources. */
  sources: Vec3[];
  /** Per source: −1 emits only the luminaire's downward hemisphere (local y < 0), +1 only the upward one, 0 all (pointSources.ts, openingSources). */
  sides: (-1 | 0 | 1)[];
  /** colour · dimming · TILT / number of sources, per channel. */
  weight: Rgb;
}

/** The near-field model in force: the settings' override, else the scene's, else 'split'. */
export function nearFieldOf(scene: BakeScene, settings: { nearField?: NearField }): NearField {
  return settings.nearField ?? scene.nearField ?? 'split';
}

/**
 * The scene's luminaires as point sources (docs/baker.md, "Luminous openings"):
 * with nearField 'split' an opening larger than `sourceSpacing` becomes a grid,
 * at the bottom and top faces of a tall opening (openingSources), with 'point'
 * each luminaire is one source at its photometric centre. Lamps that
 * emit nothing (zero dimming, black colour, all-zero candela) are dropped.
 */
export function scenePointSources(scene: BakeScene, settings: { sourceSpacing: number; maxSourcesPerAxis: number; nearField?: NearField }): LampSources[] {
  const { room } = scene;
  // The box the sources stay in: the room's, or for a shaped room baked in its enclosure the outline's
  // bounding box under the flat ceiling, in bake coordinates (as the reference takes it).
  const { min: low, max: high } = sourceBox(room);
  const split = nearFieldOf(scene, settings) === 'split';
  return scene.luminaires.flatMap((l, luminaire) => {
    // TILT data (LM-63 TILT=INCLUDE/<file>) scales the whole grid for a pitched lamp.
    const dimming = (l.dimming ?? 1) * tiltMultiplier(l.photometry, l.pitch);
    const color = l.color ?? [1, 1, 1];
    const emits = l.photometry.candela.some((row) => row.some((cd) => Number.isFinite(cd) && cd > 0));
    if (!emits || !(dimming > 0) || color.every((c) => !(c > 0))) return [];
    const rotation = luminaireRotation(l.yaw, l.pitch, l.roll);
    // Room left along the luminaire's local −y and +y (for the faces of a tall opening).
    const up = applyMat3(rotation, [0, 1, 0]);
    const exit = (sign: number) => Math.min(...[0, 1, 2].map((a) => (sign * up[a] > 1e-12 ? (high[a] - l.position[a]) / (sign * up[a]) : sign * up[a] < -1e-12 ? (low[a] - l.position[a]) / (sign * up[a]) : Infinity)));
    const { sources: local, perGrid } = split
      ? openingSources(l.photometry, settings.sourceSpacing, settings.maxSourcesPerAxis, { down: exit(-1), up: exit(1) })
      : { sources: [{ position: [0, 0, 0] as Vec3, side: 0 as const }], perGrid: 1 };
    const sources = local.map(({ position }): Vec3 => {
      const w = applyMat3(rotation, position);
      // Keep split sources inside the room (an opening flush with a wall).
      return [0, 1, 2].map((a) => Math.min(high[a], Math.max(low[a], l.position[a] + w[a]))) as Vec3;
    });
    // Each direction is emitted by one grid: 1/(grid size) of the distribution per source.
    const weight = [0, 1, 2].map((c) => (color[c] * dimming) / perGrid) as Rgb;
    return [{ luminaire, photometry: l.photometry, rotation, sources, sides: local.map((s) => s.side), weight }];
  });
}

/** The box point sources are kept in: [0, size] for a box room; a shaped room's bounding box under its flat ceiling, in bake coordinates, inside its enclosure. */
function sourceBox(room: BakeScene['room']): { min: Vec3; max: Vec3 } {
  const e = room.enclosure;
  if (!e) return { min: [0, 0, 0], max: [room.width, room.height, room.depth] };
  const xs = e.shape.corners.map((c) => c[0]);
  const zs = e.shape.corners.map((c) => c[1]);
  return {
    min: [Math.min(...xs) + e.offset[0], e.offset[1], Math.min(...zs) + e.offset[2]],
    max: [Math.max(...xs) + e.offset[0], e.shape.height + e.offset[1], Math.max(...zs) + e.offset[2]],
  };
}
