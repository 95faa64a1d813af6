/**
 * A key press as the planner's command table sees it: the key (KeyboardEvent.key) and the
 * modifiers that matter. Plain data, so tests can press keys without a DOM.
 */
export interface KeyChord {
  key: string;
  /** Ctrl, or ⌘ on a Mac: both mean the same to the planner. */
  mod?: boolean;
  shift?: boolean;
  alt?: boolean;
}

/** A chord written in a command table: 'Delete', 'r', 'Shift+r', 'Mod+Shift+z', '+'. */
export type KeySpec = string;

interface ParsedSpec {
  key: string;
  mod: boolean;
  shift: boolean;
}

function parseSpec(spec: KeySpec): ParsedSpec {
  const parts = spec.split('+');
  // '+' itself (and 'Mod++') ends in an empty part after the split: the key is '+'.
  const key = spec.endsWith('+') ? '+' : parts[parts.length - 1];
  const mods = spec.endsWith('+') ? parts.slice(0, -2) : parts.slice(0, -1);
  return { key: normaliseKey(key), mod: mods.includes('Mod'), shift: mods.includes('Shift') };
}

/** Letters compare without case: Shift+R arrives as key 'R'. Named keys ('ArrowLeft') stay as they are. */
function normaliseKey(key: string): string {
  return key.length === 1 ? key.toLowerCase() : key;
}

/**
 * Whether a pressed chord is one of `specs`. Shift picks a variant only where the table
 * names one (Shift+r, Shift+ArrowLeft, Mod+Shift+z): `ignoreShift` is the second pass that
 * lets a chord without a Shift variant match anyway, so '+' typed with Shift and
 * Shift+Delete still do what '+' and Delete do.
 */
export function chordMatches(chord: KeyChord, specs: readonly KeySpec[], ignoreShift: boolean): boolean {
  if (chord.alt) return false;
  const key = normaliseKey(chord.key);
  return specs.some((s) => {
    const p = parseSpec(s);
    return p.key === key && p.mod === Boolean(chord.mod) && (ignoreShift ? !p.shift : p.shift === Boolean(chord.shift));
  });
}

/** The first item whose keys match the chord exactly, else the first that matches ignoring Shift. */
export function findByChord<T extends { keys: readonly KeySpec[] }>(items: readonly T[], chord: KeyChord): T | undefined {
  return items.find((c) => chordMatches(chord, c.keys, false)) ?? items.find((c) => chordMatches(chord, c.keys, true));
}
