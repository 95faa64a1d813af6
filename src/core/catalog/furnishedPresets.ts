/**
 * Furnished rooms: full configurations with rails and furniture (a living room, a dining room
 * with a pendant rail over its table, a shop window), built through the same always-valid
 * actions as the planner, so each step is checked by validate(). The 3D view's first impression
 * and the demo use them. Placements are in metres on the room's plan (docs/furniture.md).
 */
import { attemptAction } from '../model/actions/actionDefinitions';
import type { Catalog } from '../model/catalogSchema/catalogSchema';
import { createConfiguration, type Configuration, type Room } from '../model/configuration/configuration';

export interface FurnishedPreset {
  readonly id: string;
  readonly name: string;
  readonly build: (catalog: Catalog) => Configuration;
}

type Step = readonly [name: string, params: Record<string, unknown>];

/** Runs the steps in order; a refused step is a bug in the preset (or a catalog without its presets): the error names it. */
function furnish(room: Partial<Room>, steps: readonly Step[], catalog: Catalog): Configuration {
  let state = createConfiguration(room);
  for (const [name, params] of steps) {
    const outcome = attemptAction(state, name, params, catalog);
    if (!outcome.ok) throw new Error(`furnished preset: ${name} ${JSON.stringify(params)} was refused: ${outcome.reason}`);
    state = outcome.next;
  }
  return state;
}

const floor = (item: string, x: number, z: number, yaw = 0): Step => ['addObject', { source: { kind: 'library', item }, placement: { on: 'floor', x, z }, yaw }];
const onWall = (item: string, wall: string, u: number, y: number): Step => ['addObject', { source: { kind: 'library', item }, placement: { on: 'wall', wall, u, y } }];

/** 6 × 5 × 2.7 m: sofa facing north from the south wall, coffee table, armchair, shelf, plant, a picture over the sofa, an L-corner rail. */
export function livingRoom(catalog: Catalog): Configuration {
  return furnish(
    { width: 6, depth: 5, height: 2.7, reflectance: { floor: [0.493, 0.327, 0.158], ceiling: 0.8, north: 0.7, south: 0.7, west: 0.7, east: 0.7 } },
    [
      ['placePreset', { presetId: 'corner-l', x: 1.5, z: 3.5, rotation: 0 }],
      floor('sofa', 3, 4.55, 180),
      floor('coffee-table', 3, 3.3),
      floor('armchair', 1, 3.2, 90),
      floor('open-shelf', 4.6, 0.175),
      floor('floor-plant', 0.45, 4.5),
      floor('person', 2, 2.2, 30),
      onWall('picture', 'south', 3, 1.5),
    ],
    catalog,
  );
}

/** 5 × 4 × 2.8 m: a table for six under a pendant rail of three spots (hung as low as head room allows), sideboard, plant, picture. */
export function diningRoom(catalog: Catalog): Configuration {
  const chairs: Step[] = [1.9, 2.5, 3.1].flatMap((x) => [floor('chair', x, 1.3, 0), floor('chair', x, 2.7, 180)]);
  const state = furnish(
    { width: 5, depth: 4, height: 2.8, reflectance: { floor: [0.226, 0.097, 0.038], ceiling: 0.8, north: 0.6, south: 0.6, west: 0.6, east: 0.6 } },
    [
      // the 1.5 m single rail centred over the table (its anchor is the rail's start)
      ['placePreset', { presetId: 'single', x: 1.75, z: 2, rotation: 0 }],
      floor('dining-table', 2.5, 2),
      ...chairs,
      floor('sideboard', 0.225, 2, 90),
      floor('floor-plant', 4.6, 0.4),
      onWall('picture', 'east', 2, 1.55),
    ],
    catalog,
  );
  // Pendant: as low as the catalog's head room allows (ceiling − minHeightAboveFloor).
  const low = Math.min(catalog.suspension.max, state.room.height - catalog.suspension.minHeightAboveFloor);
  const outcome = attemptAction(state, 'setSuspension', { systemId: state.systems[0].id, suspension: low }, catalog);
  if (!outcome.ok) throw new Error(`furnished preset: setSuspension was refused: ${outcome.reason}`);
  return outcome.next;
}

/** 7 × 4 × 3.2 m, the window on the south wall: three standing figures facing it, display plinths, shelves at the back, a long line of linears and floods. */
export function shopWindow(catalog: Catalog): Configuration {
  return furnish(
    { width: 7, depth: 4, height: 3.2, reflectance: { floor: [0.307, 0.3, 0.28], ceiling: 0.8, north: 0.8, south: 0.5, west: 0.8, east: 0.8 } },
    [
      ['placePreset', { presetId: 'long-line', x: 0.5, z: 2.6, rotation: 0 }],
      floor('person', 2, 3.3),
      floor('person', 3.5, 3.4, 20),
      floor('person', 5, 3.3, 340),
      floor('sideboard', 2.75, 2.2),
      floor('sideboard', 4.8, 2.2),
      floor('open-shelf', 1.5, 0.175),
      floor('open-shelf', 5.5, 0.175),
      floor('kitchen-island', 3.5, 0.9),
      floor('floor-plant', 6.6, 3.6),
    ],
    catalog,
  );
}

export const FURNISHED_PRESETS: readonly FurnishedPreset[] = [
  { id: 'living-room', name: 'Living room', build: livingRoom },
  { id: 'dining-room', name: 'Dining room', build: diningRoom },
  { id: 'shop-window', name: 'Shop window', build: shopWindow },
];
