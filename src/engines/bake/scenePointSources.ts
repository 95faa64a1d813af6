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
  const roomSize: Vec3 = [room.width, room.height, room.depth];
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
    const exit = (sign: number) => Math.min(...[0, 1, 2].map((a) => (sign * up[a] > 1e-12 ? (roomSize[a] - l.position[a]) / (sign * up[a]) : sign * up[a] < -1e-12 ? -l.position[a] / (sign * up[a]) : Infinity)));
    const { sources: local, perGrid } = split
      ? openingSources(l.photometry, settings.sourceSpacing, settings.maxSourcesPerAxis, { down: exit(-1), up: exit(1) })
      : { sources: [{ position: [0, 0, 0] as Vec3, side: 0 as const }], perGrid: 1 };
    const sources = local.map(({ position }): Vec3 => {
      const w = applyMat3(rotation, position);
      // Keep split sources inside the room (an opening flush with a wall).
      return [0, 1, 2].map((a) => Math.min(roomSize[a], Math.max(0, l.position[a] + w[a]))) as Vec3;
    });
    // Each direction is emitted by one grid: 1/(grid size) of the distribution per source.
    const weight = [0, 1, 2].map((c) => (color[c] * dimming) / perGrid) as Rgb;
    return [{ luminaire, photometry: l.photometry, rotation, sources, sides: local.map((s) => s.side), weight }];
  });
}
