/**
 * The DMX patch of a module (docs/live-control.md): where a lighting console's
 * channels for it sit. A patched module takes a level channel (8-bit) or two
 * (16-bit: coarse at the address, fine at address + 1), then, when `cct` is on
 * (tunable types only: more than one CCT in the catalog), one CCT channel.
 * The patch lives on the module (ModuleInstance.dmx), so removing a module
 * removes its patch by construction, and it is saved with the configuration.
 */
import type { ModuleTypeSpec } from '../catalogSchema/moduleTypeSchema';
import { keyed, type Keyed } from '../configuration/coding';
import type { Configuration, DmxPatch, ModuleInstance } from '../configuration/configuration';

export const DMX_CHANNELS = 512;
/**
 * Universe numbers as the bridge forwards them (docs/dmx.md, "Universe numbering"): sACN's own
 * 1–63999, and Art-Net Port-Address + 1, so the same physical universe has one number.
 */
export const DMX_UNIVERSE_MIN = 1;
export const DMX_UNIVERSE_MAX = 63999;

/** How many channels a patch takes. */
export function patchWidth(p: Pick<DmxPatch, 'resolution' | 'cct'>): number {
  return p.resolution / 8 + (p.cct ? 1 : 0);
}

/** A type whose CCT can be set from the console: it offers more than one. */
export function isTunable(type: Pick<ModuleTypeSpec, 'ccts'>): boolean {
  return type.ccts.length > 1;
}

/** "1/5–7": universe / first–last channel, for messages and the patch table. */
export function formatPatchRange(p: Pick<DmxPatch, 'universe' | 'address' | 'resolution' | 'cct'>): string {
  const last = p.address + patchWidth(p) - 1;
  return last === p.address ? `${p.universe}/${p.address}` : `${p.universe}/${p.address}–${last}`;
}

/** A patch's own problem (ranges, fit in the universe, CCT on a tunable type), or null. */
export function patchRangeProblem(p: DmxPatch, type: Pick<ModuleTypeSpec, 'ccts' | 'name'>): string | null {
  return patchRangeIssue(p, type)?.message ?? null;
}

/** patchRangeProblem with its sentence's code and params (docs/i18n.md). */
export function patchRangeIssue(p: DmxPatch, type: Pick<ModuleTypeSpec, 'ccts' | 'name'> & { id?: string }): ({ message: string } & Keyed) | null {
  if (!Number.isInteger(p.universe) || p.universe < DMX_UNIVERSE_MIN || p.universe > DMX_UNIVERSE_MAX)
    return keyed({ message: `DMX universe must be an integer in ${DMX_UNIVERSE_MIN}..${DMX_UNIVERSE_MAX} (got ${p.universe})` }, 'dmxUniverseRange', { min: DMX_UNIVERSE_MIN, max: DMX_UNIVERSE_MAX, value: String(p.universe) });
  if (!Number.isInteger(p.address) || p.address < 1 || p.address > DMX_CHANNELS)
    return keyed({ message: `DMX address must be an integer in 1..${DMX_CHANNELS} (got ${p.address})` }, 'dmxAddressRange', { max: DMX_CHANNELS, value: String(p.address) });
  if (p.resolution !== 8 && p.resolution !== 16) return keyed({ message: `DMX resolution must be 8 or 16 bits (got ${String(p.resolution)})` }, 'dmxResolution', { value: String(p.resolution) });
  if (p.cct && !isTunable(type)) return keyed({ message: `${type.name} has one colour temperature only: no CCT channel` }, 'dmxNoCctChannel', { name: type.name, typeId: type.id ?? '' });
  const last = p.address + patchWidth(p) - 1;
  if (last > DMX_CHANNELS) return keyed({ message: `channels ${p.address}–${last} would run past ${DMX_CHANNELS}` }, 'dmxPastEnd', { first: p.address, last, max: DMX_CHANNELS });
  return null;
}

export interface PatchedModule {
  readonly module: ModuleInstance;
  readonly patch: DmxPatch;
  /** Path of the module in the configuration, e.g. 'systems[0].rails[1].modules[2]'. */
  readonly path: string;
}

/** Every module in module order (system, rail, position on the rail), with its path. */
export function modulesInOrder(config: Configuration): { module: ModuleInstance; path: string }[] {
  return config.systems.flatMap((s, i) => s.rails.flatMap((r, k) => r.modules.map((module, n) => ({ module, path: `systems[${i}].rails[${k}].modules[${n}]` }))));
}

/** The patched modules, in module order (paths built for those only: validateResult runs this on every action). */
export function patchedModules(config: Configuration): PatchedModule[] {
  const out: PatchedModule[] = [];
  config.systems.forEach((s, i) =>
    s.rails.forEach((r, k) =>
      r.modules.forEach((module, n) => {
        if (module.dmx) out.push({ module, patch: module.dmx, path: `systems[${i}].rails[${k}].modules[${n}]` });
      }),
    ),
  );
  return out;
}

/**
 * The first pair of patched modules whose channels overlap, the later one in
 * module order first, or null. Sorted by universe and address, so a patch of
 * thousands of modules costs one sort. Entries with out-of-range numbers are
 * skipped: validate() reports those on their own.
 */
export function firstPatchOverlap(config: Configuration): { at: PatchedModule; other: PatchedModule } | null {
  const list = patchedModules(config).filter(({ patch: p }) => Number.isInteger(p.universe) && Number.isInteger(p.address) && (p.resolution === 8 || p.resolution === 16));
  if (list.length < 2) return null;
  const order = list.map((_, i) => i).sort((a, b) => list[a].patch.universe - list[b].patch.universe || list[a].patch.address - list[b].patch.address || a - b);
  let prev = order[0];
  for (let k = 1; k < order.length; k++) {
    const cur = order[k];
    const a = list[prev].patch;
    const b = list[cur].patch;
    if (a.universe === b.universe && b.address <= a.address + patchWidth(a) - 1) {
      return prev > cur ? { at: list[prev], other: list[cur] } : { at: list[cur], other: list[prev] };
    }
    // Keep the entry reaching furthest, so a wide patch is compared with every later start it covers.
    if (a.universe !== b.universe || b.address + patchWidth(b) > a.address + patchWidth(a)) prev = cur;
  }
  return null;
}

/** 0..1 from a patch's level channel(s): 8-bit v/255; 16-bit (coarse·256 + fine)/65535. Missing channels read 0. */
export function decodeLevel(channels: ArrayLike<number>, patch: Pick<DmxPatch, 'address' | 'resolution'>): number {
  const at = (i: number) => clampByte(channels[patch.address - 1 + i]);
  return patch.resolution === 16 ? (at(0) * 256 + at(1)) / 65535 : at(0) / 255;
}

/**
 * Kelvin from a CCT channel value: 0..255 linear over the type's CCT range
 * (lowest offered at 0, highest at 255). Continuous, not snapped to the offered
 * CCTs: the relight engine takes any colour (cctToLinearRgb at any kelvin), so
 * a console fade sweeps smoothly, as a tunable-white fixture does.
 */
export function cctFromChannel(value: number, type: Pick<ModuleTypeSpec, 'ccts'>): number {
  const lo = Math.min(...type.ccts);
  const hi = Math.max(...type.ccts);
  return lo + (clampByte(value) / 255) * (hi - lo);
}

/** The CCT channel's value of a patch, or null when it has none. */
export function cctChannelValue(channels: ArrayLike<number>, patch: DmxPatch): number | null {
  return patch.cct ? clampByte(channels[patch.address - 1 + patch.resolution / 8]) : null;
}

function clampByte(v: number | undefined): number {
  return typeof v === 'number' && Number.isFinite(v) ? Math.min(255, Math.max(0, Math.round(v))) : 0;
}
