/**
 * Colour filters (gels) as catalog accessories (docs/colour-filters.md): the catalog's `filters`
 * name library filters (src/core/colour) with an article and a price; module types with
 * `filterHolder: true` take one. The one rule validate() and setModuleFilter share, the catalog's
 * own check, and the colour a module gives through its filter.
 */
import { keyed } from '../configuration/coding';
import { colourFilter, type ColourFilter } from '../../colour/colourFilterLibrary';
import type { FilteredColour } from '../../colour/filteredColour';
import { moduleColour } from '../../colour/moduleColour';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { ModuleTypeSpec } from '../catalogSchema/moduleTypeSchema';
import type { Configuration, ModuleInstance } from '../configuration/configuration';

export type FilterAccessory = NonNullable<Catalog['filters']>[number];

/** The catalog's filter accessory with this id, or undefined. */
export function filterAccessory(catalog: Catalog, id: string): FilterAccessory | undefined {
  return catalog.filters?.find((f) => f.id === id);
}

/** 'LEE 204 Full C.T. Orange': how lists, the BOM and messages name a library filter. */
export function filterLabel(filter: Pick<ColourFilter, 'maker' | 'number' | 'name'>): string {
  return `${filter.maker.split(' ')[0]} ${filter.number} ${filter.name}`;
}

/** The catalog's filters with their library data, in catalog order. */
export function catalogFilters(catalog: Catalog): { accessory: FilterAccessory; filter: ColourFilter }[] {
  return (catalog.filters ?? []).flatMap((accessory) => {
    const filter = colourFilter(accessory.id);
    return filter ? [{ accessory, filter }] : [];
  });
}

/**
 * The picker's search: every word of the query (case-insensitive) found in the filter's number,
 * name or maker, so '204', 'orange', 'lee blue' and 'C.T. Blue' all find what a user means.
 */
export function filterMatches(filter: Pick<ColourFilter, 'maker' | 'number' | 'name'>, query: string): boolean {
  const text = `${filter.number} ${filter.name} ${filter.maker}`.toLowerCase();
  return query
    .toLowerCase()
    .split(/\s+/)
    .filter(Boolean)
    .every((word) => text.includes(word));
}

export interface FilterProblem {
  readonly code: 'unknown-filter' | 'no-filter-holder';
  readonly message: string;
}

/** Why `filterId` cannot sit in front of a module of `type` (null: it can). */
export function moduleFilterProblem(type: ModuleTypeSpec, filterId: string, catalog: Catalog): FilterProblem | null {
  if (!filterAccessory(catalog, filterId) || !colourFilter(filterId)) return keyed({ code: 'unknown-filter', message: `unknown colour filter '${filterId}' (not among the catalog's filters)` }, 'unknownFilter', { id: filterId });
  if (type.filterHolder !== true) return keyed({ code: 'no-filter-holder', message: `${type.name} has no filter holder: it takes no colour filter` }, 'noFilterHolder', { name: type.name, typeId: type.id });
  return null;
}

/**
 * Colours already worked out, by CCT and filter: moduleColour is a pure function of the two, and
 * each call sums Planck's law over the CMF grid and searches the locus for CCT/Duv (about 0.1 ms),
 * which toLightingScene pays per module per call (the always-valid test: a sixth of its time).
 * Bounded, so a dim-to-warm sweep through many CCTs cannot grow it without end.
 */
const colours = new Map<string, FilteredColour>();
const MAX_COLOURS = 4096;

/** The colour (linear RGB with luminance τ_v, CIE x,y, CCT/Duv) of a module's light through its filter. Shared: callers copy before changing. */
export function moduleLightColour(module: Pick<ModuleInstance, 'cct' | 'filter'>): FilteredColour {
  const key = module.filter === undefined ? String(module.cct) : `${module.cct}|${module.filter}`;
  const known = colours.get(key);
  if (known) return known;
  const colour = moduleColour(module.cct, module.filter);
  if (colours.size >= MAX_COLOURS) colours.clear();
  colours.set(key, colour);
  return colour;
}

/**
 * Every filter id a configuration uses: its modules' and its light scenes' looks (a recalled look
 * needs its filter's colour too). Hosts load the colour-filter spectra when this is not empty.
 */
export function configurationFilterIds(config: Pick<Configuration, 'systems' | 'lightScenes'>): string[] {
  const ids = new Set<string>();
  for (const s of config.systems) for (const r of s.rails) for (const m of r.modules) if (m.filter !== undefined) ids.add(m.filter);
  for (const scene of config.lightScenes ?? []) for (const look of Object.values(scene.looks)) if (look.filter !== undefined) ids.add(look.filter);
  return [...ids];
}
