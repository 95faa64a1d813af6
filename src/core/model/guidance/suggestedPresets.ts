/**
 * The first run's suggestions (issue 27, docs/planner.md "First run"): the presets to offer on an
 * empty plan, best first. The rule: a preset is a candidate when it can be placed in this room (the
 * model finds it a free spot, as placePreset does); candidates are ranked by how much of the room
 * they cover — the area of the placed system's bounding box over the floor area — largest first,
 * ties in catalog order. So a small room gets what fits it, a large one the layouts that light more of it.
 */
import { attemptAction } from '../actions/actionDefinitions';
import type { Catalog } from '../catalogSchema/catalogSchema';
import { createConfiguration, type Room } from '../configuration/configuration';
import { systemBounds } from '../rails/geometry';

export interface PresetSuggestion {
  readonly presetId: string;
  /** Bounding box of the placed preset over the room's floor area, 0–1. */
  readonly coverage: number;
}

/**
 * The `count` best presets for an empty room of this size (fewer when fewer fit). `only` (a shop's
 * own list, docs/embedding.md `firstRun.presets`): just those ids, in that order, leaving out the
 * ones that do not fit.
 */
export function suggestedPresets(room: Pick<Room, 'width' | 'depth' | 'height'>, catalog: Catalog, count = 3, only?: readonly string[]): PresetSuggestion[] {
  const empty = createConfiguration({ width: room.width, depth: room.depth, height: room.height });
  const ids = only ?? catalog.presets.map((p) => p.id);
  const out: (PresetSuggestion & { order: number })[] = [];
  ids.forEach((presetId, order) => {
    if (!catalog.presets.some((p) => p.id === presetId)) return;
    const o = attemptAction(empty, 'placePreset', { presetId }, catalog);
    if (!o.ok) return;
    const b = systemBounds(o.next.systems[0], catalog);
    const coverage = ((b.maxX - b.minX) * (b.maxZ - b.minZ)) / (room.width * room.depth);
    out.push({ presetId, coverage, order });
  });
  if (!only) out.sort((a, b) => b.coverage - a.coverage || a.order - b.order);
  return out.slice(0, Math.max(0, count)).map(({ presetId, coverage }) => ({ presetId, coverage }));
}
