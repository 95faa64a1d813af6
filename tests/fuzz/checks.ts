/**
 * Checks the fuzzer applies to what a format reader accepted, written
 * independently of the readers (they must not grade their own work): every
 * number finite, every field of the input present in the result, no key that
 * JSON.parse silently collapsed.
 */

/** Paths of non-finite numbers in a value (iterative; accepted values are small). */
export function nonFinitePaths(value: unknown, limit = 3): string[] {
  const out: string[] = [];
  const stack: [unknown, string][] = [[value, '']];
  while (stack.length > 0 && out.length < limit) {
    const [v, path] = stack.pop()!;
    if (typeof v === 'number' && !Number.isFinite(v)) out.push(`${path || '(root)'} = ${v}`);
    else if (typeof v === 'object' && v !== null) for (const [k, c] of Object.entries(v)) stack.push([c, Array.isArray(v) ? `${path}[${k}]` : `${path}.${k}`]);
  }
  return out;
}

/**
 * Object keys of `input` (parsed JSON) missing from `output` at the same path:
 * fields a reader dropped. Empty lists are nothing lost (`"objects": []`).
 */
export function droppedFields(input: unknown, output: unknown, limit = 3): string[] {
  const out: string[] = [];
  const stack: [unknown, unknown, string][] = [[input, output, '']];
  while (stack.length > 0 && out.length < limit) {
    const [a, b, path] = stack.pop()!;
    if (typeof a !== 'object' || a === null) continue;
    if (Array.isArray(a)) {
      if (!Array.isArray(b)) continue; // a type change (e.g. grey → RGB) is the reader's business, not a drop
      a.forEach((x, i) => stack.push([x, b[i], `${path}[${i}]`]));
      continue;
    }
    if (typeof b !== 'object' || b === null) continue;
    for (const [k, v] of Object.entries(a)) {
      if (!(k in b)) {
        if (!(Array.isArray(v) && v.length === 0)) out.push(`${path}.${k}`);
      } else stack.push([v, (b as Record<string, unknown>)[k], `${path}.${k}`]);
    }
  }
  return out;
}

/** Number of object keys in JSON text, by a tokenizer that knows only strings and colons. */
function keysInText(text: string): number {
  let n = 0;
  for (let i = 0; i < text.length; i++) {
    if (text[i] !== '"') continue;
    let j = i + 1;
    while (j < text.length && text[j] !== '"') j += text[j] === '\\' ? 2 : 1;
    let k = j + 1;
    while (k < text.length && ' \t\r\n'.includes(text[k])) k++;
    if (text[k] === ':') n++;
    i = j;
  }
  return n;
}

function keysInValue(value: unknown): number {
  let n = 0;
  const stack = [value];
  while (stack.length > 0) {
    const v = stack.pop();
    if (typeof v !== 'object' || v === null) continue;
    if (!Array.isArray(v)) n += Object.keys(v).length;
    for (const c of Object.values(v as object)) stack.push(c);
  }
  return n;
}

/** True when JSON.parse collapsed repeated keys of `text` (so one of the values was dropped). */
export function hadDuplicateKeys(text: string, parsed: unknown): boolean {
  return keysInText(text) > keysInValue(parsed);
}

/** Why a refusal message breaks the one-line rule, or null. */
export function messageProblem(message: string, maxLength = 200): string | null {
  if (/[\r\n\u2028\u2029]/.test(message)) return 'multi-line message';
  if (message.length > maxLength) return `message of ${message.length} characters`;
  return null;
}

/** Accepted-value problems common to every JSON format: non-finite numbers, dropped fields, collapsed duplicate keys. */
export function jsonAcceptedProblems(text: string, output: unknown): string[] {
  const problems = nonFinitePaths(output).map((p) => `non-finite ${p}`);
  let input: unknown;
  try {
    input = JSON.parse(text);
  } catch {
    return [...problems, 'accepted text that is not JSON'];
  }
  problems.push(...droppedFields(input, output).map((p) => `dropped field ${p}`));
  if (hadDuplicateKeys(text, input)) problems.push('dropped field (duplicate key)');
  return problems;
}
