import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../bake/bakeScene';
import type { LampSources } from '../bake/scenePointSources';
import { brightdataFile, type EmittingSide } from './brightdataFile';
import { num, toRadiance, vecText } from './radianceFrame';

/** Radius of the sphere that stands for one point source, metres: small against any distance that matters (1 mm). */
export const SOURCE_RADIUS = 0.001;

/** A distribution file of the export: its path inside the folder and its text. */
export interface DistributionFile {
  path: string;
  text: string;
}

const SIDE_SUFFIX: Record<EmittingSide, string> = { [-1]: '_lower', 0: '', 1: '_upper' };

/**
 * Every luminaire as Radiance light sources, the same physical problem the baker solves: each of
 * the baker's point sources (scenePointSources: one per lamp for nearField "point", the grid of
 * the luminous opening for "split") becomes a small sphere of `light` whose `brightdata`
 * modifier carries the lamp's candela distribution, turned into the world by the lamp's
 * rotation. A sphere's projected area is πr² from every side, so the multiplier
 * A1 = 1/(πr²) makes its intensity in each direction the file's value (as `ies2rad` does for a
 * spherical source, `corr` of source.cal); the light's RGB carries colour · dimming · TILT / n.
 *
 * The orientation: luxbox's world = Ry(yaw)·Rx(pitch)·Ry(roll)·local becomes, in Radiance's frame
 * (radianceFrame.ts), Rz(yaw)·Rx(pitch)·Rz(roll); the luminaire's local frame maps to Radiance's
 * source frame exactly (nadir −Y → −Z, C0 +X → +X, C90 −Z → +Y), so the transform arguments
 * `-rz roll -rx pitch -rz yaw` (applied left to right) place the distribution.
 */
export function luminairesRad(scene: BakeScene, lamps: readonly LampSources[]): { rad: string; files: DistributionFile[] } {
  const ids = new Map<Photometry, number>();
  const files = new Map<string, DistributionFile>();
  const out: string[] = [`# Luminaires: ${lamps.length} emitting, as ${lamps.reduce((n, l) => n + l.sources.length, 0)} point sources (spheres of ${SOURCE_RADIUS * 1000} mm)`];
  const { width, height, depth } = scene.room;
  const inside = (p: Vec3): Vec3 => {
    const limits = [width, height, depth];
    // Keep the whole sphere inside the room (a lamp flush with the ceiling), a shift of ≤ 1 mm.
    return p.map((x, a) => Math.min(limits[a] - SOURCE_RADIUS, Math.max(SOURCE_RADIUS, x))) as Vec3;
  };
  for (const lamp of lamps) {
    const l = scene.luminaires[lamp.luminaire];
    if (!ids.has(lamp.photometry)) ids.set(lamp.photometry, ids.size);
    const id = ids.get(lamp.photometry)!;
    const label = [lamp.photometry.manufacturer, lamp.photometry.luminaire].filter(Boolean).join(' ').replace(/\s+/g, ' ').slice(0, 100);
    out.push('', `# luminaire ${lamp.luminaire}${label ? `: ${label}` : ''} at ${vecText(l.position)} (luxbox), yaw ${num(l.yaw)} pitch ${num(l.pitch)} roll ${num(l.roll)}`);
    const sides = [...new Set(lamp.sides)].sort();
    for (const side of sides) {
      const path = `luminaires/p${id}${SIDE_SUFFIX[side]}.dat`;
      if (!files.has(path)) files.set(path, { path, text: brightdataFile(lamp.photometry, side) });
      const name = `lum${lamp.luminaire}${SIDE_SUFFIX[side]}`;
      const args = lamp.photometry.horizontalAngles.length > 1 ? ['corr', path, 'source.cal', 'src_phi', 'src_theta'] : ['corr', path, 'source.cal', 'src_theta'];
      const transform = ['-rz', num(l.roll), '-rx', num(l.pitch), '-rz', num(l.yaw)];
      out.push(
        `void brightdata ${name}_dist`,
        `${args.length + transform.length} ${[...args, ...transform].join(' ')}`,
        '0',
        `1 ${num(1 / (Math.PI * SOURCE_RADIUS * SOURCE_RADIUS))}`,
        '',
        `${name}_dist light ${name}_light`,
        '0',
        '0',
        `3 ${lamp.weight.map(num).join(' ')}`,
      );
      lamp.sources.forEach((s, k) => {
        if (lamp.sides[k] !== side) return;
        out.push('', `${name}_light sphere ${name}_s${k}`, '0', '0', `4 ${vecText(toRadiance(inside(s)))} ${num(SOURCE_RADIUS)}`);
      });
    }
  }
  return { rad: out.join('\n') + '\n', files: [...files.values()] };
}
