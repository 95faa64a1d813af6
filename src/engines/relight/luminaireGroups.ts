import type { BakeLuminaire, BakeScene } from '../bake/bakeScene';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import type { DaylightPart } from './daylightGroups';

/**
 * A relighting group: luminaires that share photometry, position set and
 * orientation, baked together once into basis maps at dimming 1 and white
 * colour. Changing a group's dimming or colour is then a weighted sum of basis
 * maps (light is linear: the theatre report's "parad" relighting, §3.5).
 *
 * The configurator dims, recolours and switches modules one by one, so a group
 * is one module's geometry: luminaires fall into the same group only when their
 * photometry, position and orientation are all identical (two lamps at the
 * same spot), which is exact because their maps are the same up to a factor.
 */
export interface LuminaireGroup {
  /** Identity of the group's geometry: stays the same while only dimming or colour change. */
  key: string;
  /** Indices into the scene's luminaire list. */
  members: number[];
  /** The group's luminaires at unit dimming and white colour: what its basis is baked from. */
  basis: BakeLuminaire[];
  /** A daylight group (daylightGroups.ts: the sky or the sun through the windows; no members, no luminaires). */
  daylight?: DaylightPart;
}

const photometryIds = new WeakMap<Photometry, number>();
let nextPhotometryId = 1;

/** A stable id per Photometry object (the app and the CLI parse each file once, so one object per file). */
function photometryId(p: Photometry): number {
  let id = photometryIds.get(p);
  if (id === undefined) {
    id = nextPhotometryId++;
    photometryIds.set(p, id);
  }
  return id;
}

/** Positions to 0.1 mm and angles to 0.001°: finer than any change a user can make, coarse enough to ignore float noise. */
export function geometryKey(l: BakeLuminaire): string {
  const p = l.position.map((v) => Math.round(v * 1e4)).join(',');
  const a = [l.yaw, l.pitch, l.roll].map((v) => Math.round(v * 1e3)).join(',');
  return `${photometryId(l.photometry)}@${p}/${a}`;
}

/** The room's part of a basis key: any change of the room invalidates every basis. */
export function roomKey(room: BakeScene['room']): string {
  return JSON.stringify([room.width, room.height, room.depth, room.reflectance]);
}

/** Groups of a scene's luminaires, in order of first appearance. */
export function groupLuminaires(luminaires: readonly BakeLuminaire[]): LuminaireGroup[] {
  const byKey = new Map<string, LuminaireGroup>();
  luminaires.forEach((l, i) => {
    const key = geometryKey(l);
    let g = byKey.get(key);
    if (!g) {
      g = { key, members: [], basis: [{ ...l, dimming: 1, color: [1, 1, 1] }] };
      byKey.set(key, g);
    }
    g.members.push(i);
  });
  return [...byKey.values()];
}

/** The RGB weight of a group: Σ dimming·colour over its members (members share geometry, so their maps add). */
export function groupWeight(group: LuminaireGroup, luminaires: readonly BakeLuminaire[]): Rgb {
  const w: Rgb = [0, 0, 0];
  for (const i of group.members) {
    const l = luminaires[i];
    const d = l.dimming ?? 1;
    const c = l.color ?? [1, 1, 1];
    for (let k = 0; k < 3; k++) w[k] += Math.max(0, d) * Math.max(0, c[k]);
  }
  return w;
}
