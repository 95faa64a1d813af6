/**
 * Shared guards for every format the product reads from untrusted JSON
 * (lighting scenes, configuration files, share links, catalogs, finishes):
 * size, nesting depth and array length checked before validation (issue 18:
 * zod and message formatting recursed to a stack overflow on 5000-deep or
 * 490 000-element inputs), duplicate keys, one-line bounded messages (zod
 * issues as `path: problem`, unknown fields with a suggestion: zodIssues.ts).
 * Limits are documented in docs/scene-format.md and docs/model.md.
 */
import type { CodedText, Coding } from './inputError';

export const INPUT_LIMITS = {
  /** Largest scene, configuration or catalog text, in characters (UTF-16 code units ≈ bytes for JSON). */
  maxTextLength: 1_000_000,
  /** Deepest nesting of objects/arrays; every real format needs fewer than 10 levels. */
  maxDepth: 32,
  /** Longest array (the largest legitimate one is a scene's 10 000 luminaires). */
  maxArrayLength: 20_000,
  /** Longest message the product shows or prints. */
  maxMessageLength: 200,
  /** Longest excerpt of the user's input quoted back in a message. */
  maxExcerpt: 40,
} as const;

/** A value as the user wrote it, bounded: numbers as written (NaN stays NaN), strings and structures cut at `max` characters. */
export function excerpt(value: unknown, max: number = INPUT_LIMITS.maxExcerpt): string {
  let out = '';
  // Recursion is bounded by the budget: every level adds at least one character.
  const put = (v: unknown): boolean => {
    if (out.length > max) return false;
    if (typeof v === 'number') out += String(v);
    else if (typeof v === 'string') out += JSON.stringify(v.length > max ? v.slice(0, max + 1) : v);
    else if (Array.isArray(v)) {
      out += '[';
      for (let i = 0; i < v.length; i++) {
        if (i > 0) out += ',';
        if (!put(v[i])) return false;
      }
      out += ']';
    } else if (typeof v === 'object' && v !== null) {
      out += '{';
      let first = true;
      for (const k of Object.keys(v)) {
        out += `${first ? '' : ','}${JSON.stringify(k.slice(0, max + 1))}:`;
        first = false;
        if (!put((v as Record<string, unknown>)[k])) return false;
      }
      out += '}';
    } else out += String(v);
    return out.length <= max;
  };
  put(value);
  return out.length > max ? `${out.slice(0, max)}…` : out;
}

/** One line (newlines and tabs become spaces), at most `max` characters (cut with an ellipsis). */
export function oneLine(message: string, max: number = INPUT_LIMITS.maxMessageLength): string {
  const flat = message.replace(/[\r\n\t\u2028\u2029]+/g, ' ');
  return flat.length > max ? `${flat.slice(0, max - 1)}…` : flat;
}

/** 'luminaires[2].position[1]' style path; '' for the root. */
export function formatPath(path: readonly PropertyKey[]): string {
  let out = '';
  for (const p of path) {
    if (out.length > 80) return `${out}…`;
    out += typeof p === 'number' ? `[${p}]` : `${out ? '.' : ''}${String(p).slice(0, INPUT_LIMITS.maxExcerpt)}`;
  }
  return out;
}

/**
 * Linear, non-recursive check of a parsed JSON value before validation: nesting
 * depth and array length. Returns `path: problem` or null.
 */
export function jsonShapeProblem(value: unknown, limits: { maxDepth?: number; maxArrayLength?: number } = {}): string | null {
  return jsonShapeIssue(value, limits)?.text ?? null;
}

/** jsonShapeProblem with a code and params for a UI (docs/i18n.md). */
export function jsonShapeIssue(value: unknown, limits: { maxDepth?: number; maxArrayLength?: number } = {}): CodedText | null {
  const maxDepth = limits.maxDepth ?? INPUT_LIMITS.maxDepth;
  const maxArray = limits.maxArrayLength ?? INPUT_LIMITS.maxArrayLength;
  // Each stack entry keeps its parent's index so the path is rebuilt only for the report.
  const nodes: { value: unknown; key: PropertyKey; parent: number; depth: number }[] = [{ value, key: '', parent: -1, depth: 0 }];
  const pathOf = (n: number): PropertyKey[] => {
    const out: PropertyKey[] = [];
    for (let i = n; i > 0; i = nodes[i].parent) out.push(nodes[i].key);
    return out.reverse().slice(0, 12);
  };
  const stack = [0];
  while (stack.length > 0) {
    const n = stack.pop()!;
    const { value: v, depth } = nodes[n];
    if (typeof v !== 'object' || v === null) continue;
    const at = () => formatPath(pathOf(n)) || '(root)';
    if (depth >= maxDepth) return { text: `${at()}: nested deeper than ${maxDepth} levels`, code: 'jsonTooDeep', params: { path: at(), max: maxDepth } };
    if (Array.isArray(v)) {
      if (v.length > maxArray) return { text: `${at()}: array of ${v.length} entries (at most ${maxArray})`, code: 'jsonArrayTooLong', params: { path: at(), count: v.length, max: maxArray } };
      for (let i = v.length - 1; i >= 0; i--) push(v[i], i, n, depth + 1);
    } else {
      const keys = Object.keys(v);
      if (keys.length > maxArray) return { text: `${at()}: object with ${keys.length} fields (at most ${maxArray})`, code: 'jsonTooManyFields', params: { path: at(), count: keys.length, max: maxArray } };
      for (let i = keys.length - 1; i >= 0; i--) push((v as Record<string, unknown>)[keys[i]], keys[i], n, depth + 1);
    }
  }
  return null;
  function push(child: unknown, key: PropertyKey, parent: number, depth: number): void {
    if (typeof child !== 'object' || child === null) return; // leaves need no entry
    nodes.push({ value: child, key, parent, depth });
    stack.push(nodes.length - 1);
  }
}

/** Line and column (1-based) of a character offset. */
export function lineColumn(text: string, offset: number): string {
  const { line, column } = lineAndColumn(text, offset);
  return `line ${line}, column ${column}`;
}

/** lineColumn as numbers, for a message's params. */
export function lineAndColumn(text: string, offset: number): { line: number; column: number } {
  let line = 1;
  let last = -1;
  for (let i = 0; i < offset && i < text.length; i++) {
    if (text.charCodeAt(i) === 10) {
      line++;
      last = i;
    }
  }
  return { line, column: offset - last };
}

/**
 * Linear scan of JSON text for keys repeated within one object (JSON.parse
 * keeps the last silently). Returns the offset of the repeated key and its
 * name, or null. Assumes nothing about validity: JSON.parse judges that.
 */
export function duplicateKey(text: string): { offset: number; key: string } | null {
  const keys: (Set<string> | null)[] = []; // per open bracket: the keys seen (null for arrays)
  let expectKey = false;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (c === 0x22 /* " */) {
      const start = i;
      let j = i + 1;
      let escaped = false;
      for (; j < text.length; j++) {
        const d = text.charCodeAt(j);
        if (escaped) escaped = false;
        else if (d === 0x5c) escaped = true;
        else if (d === 0x22) break;
      }
      const set = keys[keys.length - 1];
      if (expectKey && set) {
        let key: string;
        try {
          key = JSON.parse(text.slice(start, j + 1)) as string;
        } catch {
          return null; // malformed: JSON.parse reports it
        }
        if (set.has(key)) return { offset: start, key };
        set.add(key);
      }
      expectKey = false;
      i = j;
    } else if (c === 0x7b /* { */) {
      keys.push(new Set());
      expectKey = true;
    } else if (c === 0x5b /* [ */) {
      keys.push(null);
      expectKey = false;
    } else if (c === 0x7d || c === 0x5d /* } ] */) {
      keys.pop();
      expectKey = false;
    } else if (c === 0x2c /* , */) expectKey = keys[keys.length - 1] != null;
  }
  return null;
}

/** How a format words its size and syntax refusals (the defaults read `source: problem`). */
export interface JsonMessages {
  /** `size` is e.g. '1.4 MB'. */
  tooLarge?: (size: string) => string;
  /** `where` is 'line L, column C: ' or ''. */
  invalidJson?: (where: string, reason: string) => string;
}

/**
 * Parse untrusted JSON text: length limit, syntax (with line and column; the
 * parser's own excerpt of the text dropped), duplicate keys, then depth and
 * array length. Returns the value, or throws `makeError(message)` with a
 * one-line message naming `source`.
 */
export function parseUntrustedJson(text: string, source: string, makeError: (message: string, coding?: Coding) => Error, messages: JsonMessages = {}): unknown {
  // Codes for a UI (docs/i18n.md): `name` is the source without the quotes a reader put round a file name.
  const name = unquoted(source);
  const fail = (message: string, coding?: Coding) => makeError(oneLine(message), coding);
  if (text.length > INPUT_LIMITS.maxTextLength) {
    const size = `${(text.length / 1e6).toFixed(1)} MB`;
    const params = { name, size: Number((text.length / 1e6).toFixed(1)), max: INPUT_LIMITS.maxTextLength / 1e6 };
    throw fail(messages.tooLarge?.(size) ?? `${source}: file is too large (${size}; at most ${INPUT_LIMITS.maxTextLength / 1e6} MB)`, { code: messages.tooLarge ? 'fileTooLargeForConfiguration' : 'fileTooLarge', params });
  }
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (error) {
    const message = (error as Error).message;
    const position = /position (\d+)/.exec(message);
    const where = position ? `${lineColumn(text, Number(position[1]))}: ` : '';
    // V8 appends a quoted excerpt of the text ('Unexpected token 'x', "xyz..." is not valid JSON'); keep only the reason.
    const full = message.replace(/ in JSON at position \d+.*$/s, '').replace(/, (?:\.\.\.)?".*"(?:\.\.\.)? is not valid JSON$/s, '');
    const reason = full.length > 80 ? `${full.slice(0, 80)}…` : full;
    // The parser's reason stays the engine's words (a parameter); the sentence and the line and column are coded.
    const lc = position ? lineAndColumn(text, Number(position[1])) : null;
    const scene = messages.invalidJson !== undefined;
    const coding: Coding = lc ? { code: scene ? 'fileNotJsonAt' : 'fileInvalidJsonAt', params: { name, line: lc.line, column: lc.column, reason } } : { code: scene ? 'fileNotJson' : 'fileInvalidJson', params: { name, reason } };
    throw fail(messages.invalidJson?.(where, reason) ?? `${source}: ${where}invalid JSON (${reason})`, coding);
  }
  const dup = duplicateKey(text);
  if (dup) {
    const lc = lineAndColumn(text, dup.offset);
    throw fail(`${source}: ${lineColumn(text, dup.offset)}: field ${excerpt(dup.key).replace(/^"|"$/g, "'")} appears twice in one object`, {
      code: 'fileDuplicateField',
      params: { name, line: lc.line, column: lc.column, field: excerpt(dup.key).replace(/^"|"$/g, '') },
    });
  }
  const shape = jsonShapeIssue(value);
  if (shape) throw fail(`${source}: ${shape.text}`, { code: 'fileProblem', params: { name }, detail: shape });
  return value;
}

/** A source as a message parameter: the file name without the quotes “…” a reader put round it. */
export function unquoted(source: string): string {
  const m = /^“(.*)”$/s.exec(source);
  return m ? m[1] : source;
}
