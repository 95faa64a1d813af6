import { z as classic } from 'zod';
import { z } from 'zod/mini';
import { describe, expect, it } from 'vitest';
import { safeParseInEnglish } from '../../src/core/zodEnglish';

/**
 * luxbox's schemas were written for zod classic (which Node and the tests ran until issue 33) and
 * are now written against zod/mini. Each case is one schema in both spellings, as the rewrite
 * translated it (`x.min(n)` → `x.check(z.gte(n))` on numbers, `z.minLength(n)` on strings and
 * arrays; `.optional()` → `z.optional(x)`; `.refine`/`.superRefine` → checks; `.extend`/`.pick`
 * → functions; classic's no-op `.finite()` dropped): both must accept and refuse the same inputs,
 * with the same paths and the same English messages (mini's through safeParseInEnglish).
 */
interface Parses {
  safeParse(v: unknown): { success: boolean; data?: unknown; error?: { issues: readonly { message: string; path: PropertyKey[] }[] } };
}
const cases: { name: string; classic: Parses; mini: z.ZodMiniType; inputs: unknown[] }[] = [
  {
    name: 'number checks',
    classic: classic.number().finite().int().nonnegative().max(10),
    mini: z.number().check(z.int(), z.nonnegative(), z.lte(10)),
    inputs: [0, 3, 10, 11, -1, 2.5, 'x', Infinity, Number.NaN, undefined],
  },
  { name: 'bounds', classic: classic.number().gt(0).lt(1), mini: z.number().check(z.gt(0), z.lt(1)), inputs: [0, 0.5, 1, -2] },
  { name: 'positive, min', classic: classic.number().positive().min(0.5), mini: z.number().check(z.positive(), z.gte(0.5)), inputs: [0, 0.4, 0.5, 3] },
  {
    name: 'string length and regex',
    classic: classic
      .string()
      .min(1)
      .max(5)
      .regex(/^[a-z]+$/, 'lower-case letters'),
    mini: z.string().check(z.minLength(1), z.maxLength(5), z.regex(/^[a-z]+$/, 'lower-case letters')),
    inputs: ['', 'abc', 'abcdef', 'AB', 4],
  },
  { name: 'regex without message', classic: classic.string().regex(/^[A-Z]{3}$/), mini: z.string().check(z.regex(/^[A-Z]{3}$/)), inputs: ['EUR', 'eur'] },
  { name: 'url', classic: classic.string().url(), mini: z.string().check(z.url()), inputs: ['https://example.com/a', 'not a url'] },
  {
    name: 'array min/max of enum',
    classic: classic
      .array(classic.enum(['a', 'b']))
      .min(1)
      .max(2),
    mini: z.array(z.enum(['a', 'b'])).check(z.minLength(1), z.maxLength(2)),
    inputs: [[], ['a'], ['a', 'b', 'a'], ['c']],
  },
  {
    name: 'strict object with optional, nullable, literal',
    classic: classic.strictObject({ kind: classic.literal('k'), n: classic.number().optional(), s: classic.string().nullable() }),
    mini: z.strictObject({ kind: z.literal('k'), n: z.optional(z.number()), s: z.nullable(z.string()) }),
    inputs: [{ kind: 'k', s: null }, { kind: 'k', s: 'x', n: 2 }, { kind: 'j', s: null }, { kind: 'k', s: null, extra: 1 }, { kind: 'k' }],
  },
  {
    name: 'object strips, tuple, record',
    classic: classic.object({ t: classic.tuple([classic.number(), classic.number(), classic.number()]), r: classic.record(classic.string().max(3), classic.boolean()) }),
    mini: z.object({ t: z.tuple([z.number(), z.number(), z.number()]), r: z.record(z.string().check(z.maxLength(3)), z.boolean()) }),
    inputs: [
      { t: [1, 2, 3], r: { a: true }, extra: 1 },
      { t: [1, 2], r: {} },
      { t: [1, 2, 3], r: { a: 1 } },
      { t: [1, 2, 3], r: { long: true } },
    ],
  },
  {
    name: 'union, discriminated union',
    classic: classic.union([classic.number(), classic.discriminatedUnion('type', [classic.object({ type: classic.literal('a'), x: classic.number() }), classic.object({ type: classic.literal('b') })])]),
    mini: z.union([z.number(), z.discriminatedUnion('type', [z.object({ type: z.literal('a'), x: z.number() }), z.object({ type: z.literal('b') })])]),
    inputs: [1, { type: 'a', x: 1 }, { type: 'b' }, { type: 'c' }, { type: 'a' }],
  },
  {
    name: 'refine with message and error function, then optional',
    classic: classic
      .number()
      .refine(Number.isFinite, 'must be finite')
      .refine((v) => v < 5, { error: (i) => `${String(i.input)} is not under 5` })
      .optional(),
    mini: z.optional(
      z.number().check(
        z.refine(Number.isFinite, 'must be finite'),
        z.refine((v) => v < 5, { error: (i) => `${String(i.input)} is not under 5` }),
      ),
    ),
    inputs: [1, 7, undefined, 'x'],
  },
  {
    name: 'superRefine',
    classic: classic.array(classic.number()).superRefine((a, ctx) => {
      if (a.length % 2) ctx.addIssue({ code: 'custom', message: 'odd length', path: [a.length - 1] });
    }),
    mini: z.array(z.number()).check(
      z.superRefine((a, ctx) => {
        if (a.length % 2) ctx.addIssue({ code: 'custom', message: 'odd length', path: [a.length - 1] });
      }),
    ),
    inputs: [
      [1, 2],
      [1, 2, 3],
    ],
  },
  {
    name: 'schema params',
    classic: classic.number({ error: (i) => (i.input === undefined ? 'is missing' : 'must be a number') }),
    mini: z.number({ error: (i) => (i.input === undefined ? 'is missing' : 'must be a number') }),
    inputs: [undefined, 'x', 1],
  },
  {
    name: 'int with a message, min with a message',
    classic: classic.number().int('must be a whole number').min(0, 'must be 0 or more'),
    mini: z.number().check(z.int('must be a whole number'), z.gte(0, 'must be 0 or more')),
    inputs: [1, 1.5, -1, -1.5],
  },
  {
    name: 'custom, never',
    classic: classic.object({ c: classic.custom<{ p: number }>((v) => typeof v === 'object' && v !== null && 'p' in v, 'must have p'), n: classic.never().optional() }),
    mini: z.object({ c: z.custom<{ p: number }>((v) => typeof v === 'object' && v !== null && 'p' in v, 'must have p'), n: z.optional(z.never()) }),
    inputs: [{ c: { p: 1 } }, { c: {} }, { c: { p: 1 }, n: 1 }],
  },
  { name: 'pick', classic: classic.object({ a: classic.number(), b: classic.string() }).pick({ a: true }), mini: z.pick(z.object({ a: z.number(), b: z.string() }), { a: true }), inputs: [{ a: 1 }, { b: 'x' }] },
  {
    name: 'extend',
    classic: classic.strictObject({ version: classic.literal(2), a: classic.number() }).extend({ version: classic.literal(3), b: classic.string().optional() }),
    mini: z.extend(z.strictObject({ version: z.literal(2), a: z.number() }), { version: z.literal(3), b: z.optional(z.string()) }),
    inputs: [
      { version: 3, a: 1 },
      { version: 2, a: 1 },
      { version: 3, a: 1, b: 'x' },
      { version: 3, a: 1, c: 1 },
    ],
  },
];

describe('schemas on zod/mini agree with their zod classic spelling', () => {
  for (const c of cases) {
    it(c.name, () => {
      for (const input of c.inputs) {
        const expected = c.classic.safeParse(input);
        const actual = safeParseInEnglish(c.mini, input);
        expect(actual.success, `${c.name}: ${JSON.stringify(input)}`).toBe(expected.success);
        if (!expected.success) expect(actual.error!.issues.map((i) => [i.path, i.message])).toEqual(expected.error!.issues.map((i) => [i.path, i.message]));
        else expect(actual.data).toEqual(expected.data);
      }
    });
  }
});
