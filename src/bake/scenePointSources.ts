import type { NearField, Rgb, Vec3 } from '../model/lightingScene';
import type { Photometry } from '../photometry/types';
import { tiltMultiplier } from '../photometry/tilt';
import type { BakeScene } from './bakeScene';
import { applyMat3, luminaireRotation, type Mat3 } from './luminaireRotation';
import { pointSources } from './pointSources';

/** One luminaire as point sources in the world: what the direct pass (GPU) and directAtPoint (CPU) both evaluate. */
export interface LampSources {
  /** Index of the luminaire in the scene. */
  luminaire: number;
  photometry: Photometry;
  /** Luminaire → world rotation. */
  rotation: Mat3;
  /** World positions of its point sources. */
  sources: Vec3[];
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
 * with 'point' each luminaire is one source at its photometric centre. Lamps that
 * emit nothing (zero dimming, black colour, all-zero candela) are dropped.
 */
export function scenePointSources(
  scene: BakeScene,
  settings: { sourceSpacing: number; maxSourcesPerAxis: number; nearField?: NearField },
): LampSources[] {
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
    const local: Vec3[] = split ? pointSources(l.photometry, settings.sourceSpacing, settings.maxSourcesPerAxis) : [[0, 0, 0]];
    const sources = local.map((p): Vec3 => {
      const w = applyMat3(rotation, p);
      // Keep split sources inside the room (an opening flush with a wall).
      return [0, 1, 2].map((a) => Math.min(roomSize[a], Math.max(0, l.position[a] + w[a]))) as Vec3;
    });
    const weight = [0, 1, 2].map((c) => (color[c] * dimming) / sources.length) as Rgb;
    return [{ luminaire, photometry: l.photometry, rotation, sources, weight }];
  });
}
