import type { BakeScene } from '../bake/bakeScene';
import { encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import { surfaceLayouts } from '../bake/surfaceLayout';
import { daylightGroups } from './daylightGroups';
import { electricGroupKeys, electricOrderKeys, targetKey } from './engineWeights';
import { reconcileGroups, type GroupState } from './groupState';
import { groupLuminaires, roomKey } from './luminaireGroups';
import { objectsKey } from './objectsKey';
import type { RelightEngineState } from './relightEngineState';
import { emptyLitMaps } from './relightMaps';
import type { EngineFade, SetSceneResult } from './RelightEngine';

/** Throws unless `fade` can be shown: a fraction in [0, 1], a scene to fade to, and the same luminaires (geometry) at both ends. */
export function checkFade(st: RelightEngineState, fade: EngineFade): void {
  if (!(fade.e >= 0 && fade.e <= 1)) throw new Error(`setFade: fraction ${fade.e} is outside [0, 1]`);
  if (!st.scene) throw new Error('setFade: no scene to fade to');
  if (electricGroupKeys(fade.from) !== electricOrderKeys(st.order)) throw new Error('setFade: the scene faded from has other luminaires than the scene');
}

/** A new room (or other objects): every basis and solution is of another room. */
function changeRoom(st: RelightEngineState, next: BakeScene, nextRoom: string): void {
  st.solver.reset();
  st.bases.drop();
  st.daylightCache.clear();
  st.cache.clear();
  st.atlas = null;
  st.states = new Map();
  st.room = nextRoom;
  st.layouts = surfaceLayouts(next.room, st.settings.texelSize, st.settings.maxTextureSize);
  st.out = emptyLitMaps(st.layouts);
}

/**
 * The daylight bases of groups that leave (another time of day, date, place or sky) go to the
 * daylight cache; a daylight group without a basis takes the one kept for its key. Returns how many
 * were taken back (bakes saved).
 */
function exchangeDaylightBases(st: RelightEngineState, next: ReadonlyMap<string, GroupState>, order: readonly GroupState[]): number {
  // Taken first, kept after: the bases that leave never push out the ones coming back.
  let taken = 0;
  for (const s of order) {
    if (!s.group.daylight || s.basis) continue;
    const basis = st.daylightCache.take(s.group.key);
    if (basis) {
      s.basis = basis;
      taken++;
    }
  }
  for (const [key, s] of st.states) if (s.group.daylight && s.basis && !next.has(key)) st.daylightCache.keep(key, s.basis);
  return taken;
}

/**
 * The engine's setScene (RelightEngine.ts): the scene's groups, the luminaire groups and then the
 * daylight groups (daylightGroups.ts), reconciled with the bases baked so far by key: a group
 * whose key is known keeps its basis, so a change of the luminaires rebakes no daylight basis and
 * a change of the daylight no luminaire basis; a daylight basis that left the scene is kept and taken
 * back when its group returns (daylightBasisCache.ts). Counts the bakes (`bake`, `daylightBake`) it leaves to `step`.
 */
export function setEngineScene(st: RelightEngineState, given: BakeScene): SetSceneResult {
  // A room of any shape is lit inside its enclosure, as the baker bakes it (remembered per shape and objects: one atlas).
  const next = encloseShapedRoom(given);
  // Objects are part of the room: moving, adding or removing one is a new scene and rebakes every group.
  const nextRoom = roomKey(next.room) + objectsKey(next.objects);
  if (nextRoom !== st.room) changeRoom(st, next, nextRoom);
  st.scene = next;
  const electric = groupLuminaires(next.luminaires);
  st.given = given;
  const groups = [...electric, ...daylightGroups(given, next, st.sources === 'daylight-factor')];
  const reconciled = reconcileGroups(st.states, groups);
  const bake = reconciled.bake - exchangeDaylightBases(st, reconciled.states, reconciled.order);
  st.states = reconciled.states;
  st.order = reconciled.order;
  const daylight = reconciled.order.filter((s) => s.group.daylight);
  // A basis under way for a group that is gone (moved, removed, another time of day) is of no use.
  st.bases.keepOnly(st.states);
  // A fade from a scene with other luminaires (a module added or moved meanwhile) cannot be shown: the scene is.
  if (st.fade && electricGroupKeys(st.fade.from) !== electric.map((g) => g.key).join('|')) st.fade = null;
  // A solve under way for other weights is of no use any more (the shown one stays until the new solve is done).
  st.solver.dropUnless(targetKey(st));
  if (bake === 0) st.counters.relightsOnly++;
  st.version++;
  return { bake, reused: groups.length - bake, ...(daylight.length > 0 ? { daylightBake: daylight.filter((s) => !s.basis).length } : {}) };
}
