/**
 * Zod issues worded for people (the formats of untrustedJson.ts): `path: problem`, the issue coded
 * for a UI (docs/i18n.md), an unknown field with the known name it most likely misspells.
 */
import type { z } from 'zod/mini';
import type { CodedText } from './inputError';
import { excerpt, formatPath } from './untrustedJson';

/** Levenshtein distance, capped (returns cap + 1 once it is exceeded); names are short. */
function distance(a: string, b: string, cap: number): number {
  if (Math.abs(a.length - b.length) > cap) return cap + 1;
  let prev = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const row = [i];
    for (let j = 1; j <= b.length; j++) row[j] = Math.min(prev[j] + 1, row[j - 1] + 1, prev[j - 1] + (a[i - 1].toLowerCase() === b[j - 1].toLowerCase() ? 0 : 1));
    prev = row;
  }
  return prev[b.length];
}

/** The known name closest to a misspelt one (edit distance ≤ 2, or ≤ 1 for short names), if any. */
export function suggestField(key: string, known: Iterable<string>): string | undefined {
  if (key.length > 64) return undefined;
  const cap = key.length <= 4 ? 1 : 2;
  let best: string | undefined;
  let bestD = cap + 1;
  for (const k of known) {
    const d = distance(key, k, cap);
    if (d < bestD) [best, bestD] = [k, d];
  }
  return best;
}

/** `unknown field 'nearFeild' (did you mean 'nearField'?)`, the key shown bounded. */
export function unknownFieldMessage(key: string, known: Iterable<string>): string {
  const hint = suggestField(key, known);
  return `unknown field ${excerpt(key).replace(/^"|"$/g, "'")}${hint ? ` (did you mean '${hint}'?)` : ''}`;
}

/** Every object key a zod schema knows (for suggestions), collected once per schema. */
export function schemaFieldNames(schema: z.ZodMiniType): Set<string> {
  const names = new Set<string>();
  const seen = new Set<unknown>();
  const visit = (s: unknown): void => {
    if (!s || typeof s !== 'object' || seen.has(s)) return;
    seen.add(s);
    const def = (s as { _zod?: { def?: Record<string, unknown> } })._zod?.def;
    if (!def) return;
    if (def.type === 'object' && def.shape && typeof def.shape === 'object') {
      for (const [k, v] of Object.entries(def.shape as Record<string, unknown>)) {
        names.add(k);
        visit(v);
      }
    }
    for (const key of ['innerType', 'element', 'in', 'out', 'schema', 'left', 'right', 'rest']) visit(def[key]);
    for (const key of ['options', 'items']) if (Array.isArray(def[key])) (def[key] as unknown[]).forEach(visit);
  };
  visit(schema);
  return names;
}

/**
 * The issue to report, as `path: problem` (no source): unknown fields first (a
 * misspelt required field is better reported as the misspelling than as
 * missing), then the first issue in document order.
 */
export function describeIssues(issues: readonly z.core.$ZodIssue[], known: Iterable<string>, pathPrefix: readonly PropertyKey[] = []): string {
  return describeIssueCoded(issues, known, pathPrefix).text;
}

/**
 * describeIssues with a code and params for a UI (docs/i18n.md): a missing field, a value of the
 * wrong type, an unknown field (with its suggestion), a number out of range, a value not among
 * those allowed; any other issue is `fieldInvalid` with zod's (or the schema's) English words.
 */
export function describeIssueCoded(issues: readonly z.core.$ZodIssue[], known: Iterable<string>, pathPrefix: readonly PropertyKey[] = []): CodedText {
  const unknown = issues.find((i) => i.code === 'unrecognized_keys');
  const issue = unknown ?? issues[0];
  const where = formatPath([...pathPrefix, ...issue.path]);
  const problem = issue.code === 'unrecognized_keys' ? unknownFieldMessage(String(issue.keys[0]), known) : issue.message;
  const path = issue.code === 'unrecognized_keys' ? formatPath([...pathPrefix, ...issue.path, String(issue.keys[0])]) : where;
  const text = `${path || '(root)'}: ${problem}`;
  const at = path || '(root)';
  if (issue.code === 'unrecognized_keys') {
    const field = excerpt(String(issue.keys[0])).replace(/^"|"$/g, '');
    const hint = suggestField(String(issue.keys[0]), known);
    return hint ? { text, code: 'fieldUnknownHint', params: { path: at, field, hint } } : { text, code: 'fieldUnknown', params: { path: at, field } };
  }
  if (issue.code === 'invalid_type') {
    // zod 4 reports a missing field as an invalid type whose input is undefined.
    if (issue.input === undefined) return { text, code: 'fieldMissing', params: { path: at, expected: String(issue.expected) } };
    return { text, code: 'fieldWrongType', params: { path: at, expected: String(issue.expected) } };
  }
  if (issue.code === 'too_small' && typeof issue.minimum === 'number' && issue.origin === 'number') return { text, code: 'fieldTooSmall', params: { path: at, min: issue.minimum } };
  if (issue.code === 'too_big' && typeof issue.maximum === 'number' && issue.origin === 'number') return { text, code: 'fieldTooBig', params: { path: at, max: issue.maximum } };
  if (issue.code === 'invalid_value') return { text, code: 'fieldNotAllowed', params: { path: at, allowed: issue.values.map((v) => excerpt(v)).join(', ') } };
  return { text, code: 'fieldInvalid', params: { path: at, problem } };
}
