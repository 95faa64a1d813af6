import type { NearField } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from './bakeScene';
import type { DirectLamp } from './generateDirectShader';
import { buildProfileTable, type ProfileLookupMode, type ProfileTable } from './profileTable';
import { scenePointSources } from './scenePointSources';

/** The scene's luminaires ready for the direct pass: one profile table and the lamps that emit. */
export interface PreparedLamps {
  /** Every distinct photometry of the scene once (profileTable.ts). */
  table: ProfileTable;
  /** Lamps with their profile's layout in the table; lamps whose profile has no positive candela are left out. */
  lamps: DirectLamp[];
  /** Point sources of those lamps, for the report. */
  pointSources: number;
}

/**
 * Lamp preparation, no GL: each distinct Photometry object goes once into the
 * profile table (the same file used by many luminaires is uploaded once),
 * and every luminaire becomes its point sources (near-field model, TILT,
 * dimming and colour: scenePointSources.ts, shared with the CPU directAtPoint).
 */
export function prepareLamps(scene: BakeScene, settings: { sourceSpacing: number; maxSourcesPerAxis: number; nearField?: NearField; profileLookup?: ProfileLookupMode }): PreparedLamps {
  const distinct: Photometry[] = [];
  const profileIndex = new Map<Photometry, number>();
  for (const l of scene.luminaires) {
    if (!profileIndex.has(l.photometry)) {
      profileIndex.set(l.photometry, distinct.length);
      distinct.push(l.photometry);
    }
  }
  const table = buildProfileTable(distinct, settings.profileLookup ?? 'dense');
  let pointSources = 0;
  const lamps = scenePointSources(scene, settings).flatMap((l) => {
    const profile = table.layouts[profileIndex.get(l.photometry)!];
    if (profile.peakCandela <= 0) return [];
    pointSources += l.sources.length;
    return [{ profile, rotation: l.rotation, sources: l.sources, sides: l.sides, weight: l.weight } satisfies DirectLamp];
  });
  return { table, lamps, pointSources };
}
