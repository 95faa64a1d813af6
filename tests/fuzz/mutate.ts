/**
 * Mutation engine for the format fuzzer (issue 18): deterministic (seeded
 * PRNG), structure-aware where the seed is JSON (unknown and duplicated keys,
 * type swaps, extreme numbers, deep nesting, huge arrays) and byte-level
 * everywhere (flips, truncation, huge numerals). Deep and huge values are
 * spliced into the text through placeholders, so building an input never
 * recurses or allocates half a million objects.
 */

/** mulberry32: small, fast, good enough for fuzzing, and identical on every machine. */
export function createRng(seed: number): Rng {
  let a = seed >>> 0;
  const next = (): number => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return {
    next,
    int: (n) => Math.floor(next() * n),
    pick: (list) => list[Math.floor(next() * list.length)],
    chance: (p) => next() < p,
  };
}

export interface Rng {
  /** Uniform in [0, 1). */
  next(): number;
  /** Integer in [0, n). */
  int(n: number): number;
  pick<T>(list: readonly T[]): T;
  chance(p: number): boolean;
}

type Json = null | boolean | number | string | Json[] | { [key: string]: Json };
type Container = Json[] | { [key: string]: Json };

/** Every container in the tree with its parent link (iterative; seeds are small). */
function containers(root: Json): { node: Container; parent: Container | null; key: string | number | null }[] {
  const out: { node: Container; parent: Container | null; key: string | number | null }[] = [];
  const stack: { node: Json; parent: Container | null; key: string | number | null }[] = [{ node: root, parent: null, key: null }];
  while (stack.length > 0) {
    const { node, parent, key } = stack.pop()!;
    if (typeof node !== 'object' || node === null) continue;
    out.push({ node, parent, key });
    if (Array.isArray(node)) node.forEach((v, i) => stack.push({ node: v, parent: node, key: i }));
    else for (const k of Object.keys(node)) stack.push({ node: node[k], parent: node, key: k });
  }
  return out;
}

/** A random (container, key) slot holding a value, or null for an empty tree. */
function randomSlot(root: Json, rng: Rng): { node: Container; key: string | number } | null {
  const slots: { node: Container; key: string | number }[] = [];
  for (const { node } of containers(root)) {
    if (Array.isArray(node)) node.forEach((_, i) => slots.push({ node, key: i }));
    else for (const k of Object.keys(node)) slots.push({ node, key: k });
  }
  return slots.length > 0 ? rng.pick(slots) : null;
}

const setSlot = (node: Container, key: string | number, value: Json): void => {
  (node as Record<string | number, Json>)[key] = value;
};
const getSlot = (node: Container, key: string | number): Json => (node as Record<string | number, Json>)[key];

/** Numbers JSON can and cannot hold, and boundary values of every range in the formats. */
export const EXTREME_NUMBERS = ['1e308', '-1e308', '1.7976931348623157e308', '5e-324', '-5e-324', '-0', '1e309', '-1e999', '0', '-1', '1', '0.95', '0.9999999999999999', '360', '1e-9', '4294967296', '9007199254740993'];
/** Not JSON, but what careless writers emit. */
const NON_JSON_NUMBERS = ['NaN', 'Infinity', '-Infinity', '+1', '.5', '01', '0x10', '1e', '--1'];

function randomWord(rng: Rng): string {
  const n = 1 + rng.int(12);
  let s = '';
  for (let i = 0; i < n; i++) s += 'abcdefghijklmnopqrstuvwxyz_$-'[rng.int(29)];
  return s;
}

/** A plausible misspelling of a field name: a doubled, dropped or swapped letter, or a case change. */
export function misspell(key: string, rng: Rng): string {
  if (key.length < 2) return key + key;
  const i = rng.int(key.length - 1);
  switch (rng.int(4)) {
    case 0:
      return key.slice(0, i) + key[i] + key.slice(i);
    case 1:
      return key.slice(0, i) + key.slice(i + 1);
    case 2:
      return key.slice(0, i) + key[i + 1] + key[i] + key.slice(i + 2);
    default:
      return key.slice(0, i) + key[i].toUpperCase() + key.slice(i + 1);
  }
}

function randomValue(rng: Rng, depth = 0): Json {
  switch (rng.int(depth > 2 ? 5 : 7)) {
    case 0:
      return null;
    case 1:
      return rng.chance(0.5);
    case 2:
      return rng.chance(0.5) ? rng.int(1000) : (rng.next() - 0.5) * 10 ** rng.int(12);
    case 3:
      return rng.pick(['', 'x', 'straight', 'spot', 's1', 'r2', '../../etc/passwd', 'ies/missing.ies', '\u0000', '\ud800', '日本', 'a'.repeat(rng.int(3000))]);
    case 4:
      return rng.chance(0.5) ? [] : {};
    case 5:
      return Array.from({ length: rng.int(4) }, () => randomValue(rng, depth + 1));
    default:
      return Object.fromEntries(Array.from({ length: rng.int(3) }, () => [randomWord(rng), randomValue(rng, depth + 1)]));
  }
}

/** Placeholder string values, replaced in the text after JSON.stringify by the raw text of hole n. */
const HOLE = (n: number) => `\u0001hole${n}\u0001`;

interface Draft {
  root: Json;
  holes: string[];
}

type StructureMutation = (d: Draft, rng: Rng) => string;

const structureMutations: Record<string, StructureMutation> = {
  unknownKey(d, rng) {
    const objs = containers(d.root).filter((c) => !Array.isArray(c.node));
    if (objs.length === 0) return 'unknownKey (none)';
    const obj = rng.pick(objs).node as Record<string, Json>;
    const keys = Object.keys(obj);
    const known = containers(d.root).flatMap((c) => (Array.isArray(c.node) ? [] : Object.keys(c.node)));
    const key = keys.length > 0 && rng.chance(0.5) ? misspell(rng.pick(keys), rng) : rng.chance(0.5) && known.length > 0 ? rng.pick(known) : randomWord(rng);
    if (key in obj) return 'unknownKey (exists)';
    obj[key] = keys.length > 0 && rng.chance(0.5) ? obj[rng.pick(keys)] : randomValue(rng);
    return `unknownKey ${key}`;
  },
  removeKey(d, rng) {
    const objs = containers(d.root).filter((c) => !Array.isArray(c.node) && Object.keys(c.node).length > 0);
    if (objs.length === 0) return 'removeKey (none)';
    const obj = rng.pick(objs).node as Record<string, Json>;
    const key = rng.pick(Object.keys(obj));
    delete obj[key];
    return `removeKey ${key}`;
  },
  typeSwap(d, rng) {
    const slot = randomSlot(d.root, rng);
    if (!slot) return 'typeSwap (none)';
    setSlot(slot.node, slot.key, randomValue(rng));
    return `typeSwap ${String(slot.key)}`;
  },
  extremeNumber(d, rng) {
    const slot = randomSlot(d.root, rng);
    if (!slot) return 'extremeNumber (none)';
    const n = rng.pick(rng.chance(0.8) ? EXTREME_NUMBERS : NON_JSON_NUMBERS);
    d.holes.push(n);
    setSlot(slot.node, slot.key, HOLE(d.holes.length - 1));
    return `extremeNumber ${String(slot.key)}=${n}`;
  },
  numberTweak(d, rng) {
    const nums = containers(d.root).flatMap((c) => (Array.isArray(c.node) ? c.node.map((_, i) => i) : Object.keys(c.node)).filter((k) => typeof getSlot(c.node, k) === 'number').map((k) => ({ node: c.node, key: k })));
    if (nums.length === 0) return 'numberTweak (none)';
    const { node, key } = rng.pick(nums);
    const v = getSlot(node, key) as number;
    const next = rng.pick([v + 0.1, v - 0.1, v * 2, -v, v * 1.0000001, Math.round(v), v + 1e-12, v / 3, 0, v * 1e6]);
    setSlot(node, key, next);
    return `numberTweak ${String(key)}`;
  },
  deepNesting(d, rng) {
    const slot = randomSlot(d.root, rng);
    if (!slot) return 'deepNesting (none)';
    const levels = rng.chance(0.7) ? 5000 : rng.pick([31, 32, 33, 100, 20_000]);
    const [open, close] = rng.chance(0.5) ? ['[', ']'] : ['{"a":', '}'];
    d.holes.push(open.repeat(levels) + JSON.stringify(getSlot(slot.node, slot.key) ?? 1) + close.repeat(levels));
    setSlot(slot.node, slot.key, HOLE(d.holes.length - 1));
    return `deepNesting ${String(slot.key)} ${levels}`;
  },
  hugeArray(d, rng) {
    const arrays = containers(d.root).filter((c) => Array.isArray(c.node) && c.parent !== null);
    const target = arrays.length > 0 && rng.chance(0.8) ? rng.pick(arrays) : null;
    const slot = target ? { node: target.parent as Container, key: target.key as string | number } : randomSlot(d.root, rng);
    if (!slot) return 'hugeArray (none)';
    const n = rng.pick([500_000, 500_000, 30_000, 20_001, 19_999]);
    const current = getSlot(slot.node, slot.key);
    const element = Array.isArray(current) && current.length > 0 ? JSON.stringify(current[rng.int(current.length)]) : rng.pick(['0', '1', 'null', '"x"', '{}']);
    // Cap the text near 1.1 MB: past the size limit either way, without building giant strings.
    const count = Math.min(n, Math.floor(1_100_000 / (element.length + 1)));
    d.holes.push(`[${new Array(count).fill(element).join(',')}]`);
    setSlot(slot.node, slot.key, HOLE(d.holes.length - 1));
    return `hugeArray ${String(slot.key)} ${count}`;
  },
  duplicateElement(d, rng) {
    const arrays = containers(d.root).filter((c) => Array.isArray(c.node) && c.node.length > 0);
    if (arrays.length === 0) return 'duplicateElement (none)';
    const list = rng.pick(arrays).node as Json[];
    const times = rng.pick([1, 1, 2, 50, 600]);
    const element = list[rng.int(list.length)];
    for (let i = 0; i < times; i++) list.push(structuredClone(element));
    return `duplicateElement x${times}`;
  },
};

type TextMutation = (text: string, rng: Rng) => string;

const textMutations: Record<string, TextMutation> = {
  byteFlip: (t) => t, // applied on bytes, below
  truncate(t, rng) {
    return t.slice(0, rng.int(t.length + 1));
  },
  hugeNumeral(t, rng) {
    const numbers = [...t.matchAll(/-?\d+(\.\d+)?([eE][-+]?\d+)?/g)];
    if (numbers.length === 0) return t;
    const m = rng.pick(numbers);
    const digits = rng.pick([400, 5000, 100_000, 300_000]);
    const numeral = rng.chance(0.5) ? '9'.repeat(digits) : `0.${'0'.repeat(digits)}1`;
    return t.slice(0, m.index) + numeral + t.slice(m.index + m[0].length);
  },
  duplicateKey(t, rng) {
    // Repeat a "key": value pair inside its own object: JSON.parse would keep the last silently.
    const keys = [...t.matchAll(/"([^"\\]{1,40})"\s*:\s*("[^"\\]*"|-?[\d.eE+-]+|true|false|null)/g)];
    if (keys.length === 0) return t;
    const m = rng.pick(keys);
    const other = rng.chance(0.5) ? m[2] : JSON.stringify(randomWord(rng));
    return `${t.slice(0, m.index)}"${m[1]}": ${other}, ${t.slice(m.index)}`;
  },
  insertText(t, rng) {
    const at = rng.int(t.length + 1);
    const junk = rng.pick(['\n', ',', '}', ']', '{', '[', '"', '\\', '//', '/*x*/', '\u2028', '\ufeff', '\u0000', 'null', '"\ud800"']);
    return t.slice(0, at) + junk + t.slice(at);
  },
};

export const MUTATION_NAMES = [...Object.keys(structureMutations), ...Object.keys(textMutations)];

const utf8 = new TextEncoder();
const utf8Decoder = new TextDecoder('utf-8', { fatal: false });

/** How a format's bytes become text: UTF-8 for JSON, Latin-1 (byte = character) for photometric files. */
export type TextEncoding = 'utf8' | 'latin1';

const codecs: Record<TextEncoding, { decode(b: Uint8Array): string; encode(t: string): Uint8Array }> = {
  utf8: { decode: (b) => utf8Decoder.decode(b), encode: (t) => utf8.encode(t) },
  latin1: {
    decode: (b) => {
      let s = '';
      for (let i = 0; i < b.length; i += 8192) s += String.fromCharCode(...b.subarray(i, i + 8192));
      return s;
    },
    encode: (t) => Uint8Array.from(t, (c) => c.charCodeAt(0) & 0xff),
  },
};

function flipBytes(bytes: Uint8Array, rng: Rng): Uint8Array {
  const out = bytes.slice();
  const n = 1 + rng.int(8);
  for (let i = 0; i < n && out.length > 0; i++) out[rng.int(out.length)] ^= 1 << rng.int(8);
  return out;
}

/**
 * One mutant of a seed: 1-3 mutations, structure-level ones first (when the
 * seed is JSON), text and byte ones after. Returns the bytes and what was done.
 */
export function mutate(seed: Uint8Array, rng: Rng, encoding: TextEncoding = 'utf8'): { bytes: Uint8Array; applied: string[] } {
  const { decode, encode } = codecs[encoding];
  const applied: string[] = [];
  const count = 1 + rng.int(3);
  const names = Array.from({ length: count }, () => rng.pick(MUTATION_NAMES));
  const structural = names.filter((n) => n in structureMutations);
  let text = decode(seed);
  if (structural.length > 0) {
    let root: Json | undefined;
    try {
      root = JSON.parse(text) as Json;
    } catch {
      root = undefined;
    }
    if (root !== undefined) {
      const draft: Draft = { root, holes: [] };
      for (const n of structural) applied.push(structureMutations[n](draft, rng));
      text = JSON.stringify(draft.root, null, rng.chance(0.5) ? 2 : undefined);
      draft.holes.forEach((h, i) => (text = text.replace(JSON.stringify(HOLE(i)), () => h)));
    }
  }
  let bytes: Uint8Array | null = null;
  for (const n of names.filter((x) => x in textMutations)) {
    applied.push(n);
    if (n === 'byteFlip') bytes = flipBytes(bytes ?? encode(text), rng);
    else {
      if (bytes) text = decode(bytes);
      bytes = null;
      text = textMutations[n](text, rng);
    }
  }
  return { bytes: bytes ?? encode(text), applied };
}
