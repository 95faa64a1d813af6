import { describe, expect, it } from 'vitest';
import { functionLengths, longFunctionViolations, readFunctionLengths } from './longFunctions';

/** A function a reader takes in at once fits a screen or two (issue 28): 80 lines. */
const LIMIT = 80;

/**
 * Functions allowed past the limit, `file:name` → why. Empty since 2026-11-27 (issue 28: every
 * function in src/ is at most 80 lines); an entry whose function is gone or short again fails the
 * test below, so the list can only shrink, and a new long function fails the first test.
 */
const ALLOWED: ReadonlyMap<string, string> = new Map([]);

describe('long functions', () => {
  const all = readFunctionLengths('src');

  it(`no function in src/ is longer than ${LIMIT} lines except the reasoned allow-list`, () => {
    // The walk sees the whole tree and measures real lengths (so an empty list cannot pass).
    expect(all.length).toBeGreaterThan(2000);
    expect(all.some((f) => f.lines > 40)).toBe(true);
    expect(longFunctionViolations(all, LIMIT, new Set(ALLOWED.keys()))).toEqual([]);
  });

  it('every allow-list entry names a function that is still too long (the list only shrinks)', () => {
    const long = new Set(all.filter((f) => f.lines > LIMIT).map((f) => `${f.file}:${f.name}`));
    expect([...ALLOWED.keys()].filter((k) => !long.has(k))).toEqual([]);
    for (const reason of ALLOWED.values()) expect(reason.length).toBeGreaterThan(10);
  });

  it('the same check reports a long function, arrow, method and callback, and leaves a short one alone', () => {
    const body = (n: number) => Array.from({ length: n }, (_, i) => `  total += ${i};`).join('\n');
    const text = [
      `export function longOne(): number {\n  let total = 0;\n${body(85)}\n  return total;\n}`,
      `export const longArrow = (): number => {\n  let total = 0;\n${body(79)}\n  return total;\n};`,
      `export const shortArrow = (): number => {\n  let total = 0;\n${body(10)}\n  return total;\n};`,
      `class Holder {\n  method(): number {\n    let total = 0;\n${body(90)}\n    return total;\n  }\n}`,
      `useEffect(() => {\n  let total = 0;\n${body(100)}\n});`,
    ].join('\n\n');
    const found = functionLengths('src/fake/longOne.tsx', text);
    const byName = new Map(found.map((f) => [f.name, f]));
    // Lines from the first token to the last: `function … {`, `let`, 85 sums, `return`, `}`.
    expect(byName.get('longOne')).toMatchObject({ line: 1, lines: 89 });
    expect(byName.get('longArrow')?.lines).toBe(83);
    expect(byName.get('shortArrow')?.lines).toBe(14);
    expect(byName.get('method')?.lines).toBe(94);
    expect(byName.get('<useEffect callback>')?.lines).toBe(103);
    const problems = longFunctionViolations(found, LIMIT, new Set(['src/fake/longOne.tsx:method']));
    expect(problems).toEqual([
      'src/fake/longOne.tsx:longOne (line 1) is 89 lines, over 80',
      `src/fake/longOne.tsx:longArrow (line ${byName.get('longArrow')!.line}) is 83 lines, over 80`,
      `src/fake/longOne.tsx:<useEffect callback> (line ${byName.get('<useEffect callback>')!.line}) is 103 lines, over 80`,
    ]);
  });
});
