import type { ActionParams } from '../../core/model/actions/actionDefinitions';
import type { MeshUnits, ObjectPlacement } from '../../core/model/configuration/configuration';
import { freeFloorSpot } from '../../core/model/objects/freeFloorSpot';
import { findFurnitureItem, furnitureMesh } from '../../core/model/objects/furniture/furnitureLibrary';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { wallPlacementNear } from './objectMoves';
import type { PlannerGestureHost, RefusalToShow } from './plannerGestureHost';
import { type ScreenPoint, screenToWorld } from './viewTransform';
import { insideRoom, visibleCentre } from './visibleCentre';

/** Shows a refusal in the status line and returns its reason. */
function refused(host: PlannerGestureHost, r: RefusalToShow): string {
  host.explainRefusal(r);
  return r.reason;
}

/** Adds an object and selects it; returns the refusal, if any. */
function addObject(host: PlannerGestureHost, params: ActionParams<'addObject'>): string | null {
  const r = host.store.getState().dispatch('addObject', params);
  if (!r.ok) return refused(host, r);
  const objects = host.store.getState().config.objects;
  host.store.getState().select({ kind: 'object', id: objects[objects.length - 1].id });
  return null;
}

/**
 * Adds a furniture library item where it was dropped (`at`, plan pixels) or, tapped in the
 * panel, at the middle of the visible plan — a floor item at the nearest free floor there
 * (freeFloorSpot: never inside another piece); a wall item goes on the nearest wall at its
 * hanging height. The model moves it to the nearest spot where it fits. The new object is
 * selected. Returns the refusal, if any (also shown in the status line).
 */
export function addLibraryItem(host: PlannerGestureHost, itemId: string, at?: ScreenPoint): string | null {
  const item = findFurnitureItem(itemId);
  if (!item) return refused(host, { reason: `no furniture item '${itemId}' in the library` });
  const { config } = host.store.getState();
  const { room } = config;
  const p = at ? insideRoom(room, screenToWorld(host.view, at)) : visibleCentre(room, host.view, host.viewport);
  const free = item.mount === 'wall' ? null : freeFloorSpot(config, furnitureMesh(itemId), p);
  const placement: ObjectPlacement = item.mount === 'wall' ? wallPlacementNear(room, p, Math.min(item.hangHeight ?? room.height / 2, room.height - item.height / 2)) : { on: 'floor', x: free?.x ?? p.x, z: free?.z ?? p.z };
  return addObject(host, { source: { kind: 'library', item: itemId }, placement });
}

/** Adds an imported model (already read and converted to metres) at the middle of the visible plan and selects it. */
export function addImportedModel(host: PlannerGestureHost, name: string, mesh: TriangleMesh, units: MeshUnits): string | null {
  const { config } = host.store.getState();
  const c = visibleCentre(config.room, host.view, host.viewport);
  const free = freeFloorSpot(config, mesh, c) ?? c;
  return addObject(host, { source: { kind: 'import', name, mesh, units }, placement: { on: 'floor', x: free.x, z: free.z } });
}
