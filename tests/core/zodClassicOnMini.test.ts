import { z as classic } from 'zod';
import { describe, expect, it } from 'vitest';
import { z as mini } from '../../src/core/zodClassicOnMini';

/**
 * The browser build's `zod` (classic's API on zod/mini, vite.config.ts) against zod classic itself:
 * the same schemas, built the same way through both, must accept and refuse the same inputs with
 * the same first message and path. (The model's own tests also run against it:
 * LUXBOX_ZOD_MINI=1 npx vitest run tests/core/model.)
 */
type Z = typeof classic;

const cases: { name: string; build: (z: Z) => { safeParse(v: unknown): { success: boolean; error?: { issues: { message: string; path: PropertyKey[] }[] } } }; inputs: unknown[] }[] = [
  { name: 'number checks', build: (z) => z.number().int().nonnegative().max(10), inputs: [0, 3, 10, 11, -1, 2.5, 'x', Infinity, Number.NaN, undefined] },
  { name: 'bounds', build: (z) => z.number().gt(0).lt(1), inputs: [0, 0.5, 1, -2] },
  { name: 'positive, min', build: (z) => z.number().positive().min(0.5), inputs: [0, 0.4, 0.5, 3] },
  {
    name: 'string length and regex',
    build: (z) =>
      z
        .string()
        .min(1)
        .max(5)
        .regex(/^[a-z]+$/),
    inputs: ['', 'abc', 'abcdef', 'AB', 4],
  },
  { name: 'url', build: (z) => z.string().url(), inputs: ['https://example.com/a', 'not a url'] },
  {
    name: 'array min/max of enum',
    build: (z) =>
      z
        .array(z.enum(['a', 'b']))
        .min(1)
        .max(2),
    inputs: [[], ['a'], ['a', 'b', 'a'], ['c']],
  },
  {
    name: 'strict object with optional, nullable, literal',
    build: (z) => z.strictObject({ kind: z.literal('k'), n: z.number().optional(), s: z.string().nullable() }),
    inputs: [{ kind: 'k', s: null }, { kind: 'k', s: 'x', n: 2 }, { kind: 'j', s: null }, { kind: 'k', s: null, extra: 1 }, { kind: 'k' }],
  },
  {
    name: 'object strips, tuple, record',
    build: (z) => z.object({ t: z.tuple([z.number(), z.number(), z.number()]), r: z.record(z.string(), z.boolean()) }),
    inputs: [
      { t: [1, 2, 3], r: { a: true } },
      { t: [1, 2], r: {} },
      { t: [1, 2, 3], r: { a: 1 } },
    ],
  },
  {
    name: 'union, discriminated union',
    build: (z) => z.union([z.number(), z.discriminatedUnion('type', [z.object({ type: z.literal('a'), x: z.number() }), z.object({ type: z.literal('b') })])]),
    inputs: [1, { type: 'a', x: 1 }, { type: 'b' }, { type: 'c' }, { type: 'a' }],
  },
  {
    name: 'refine with message and error function',
    build: (z) =>
      z
        .number()
        .refine(Number.isFinite, 'must be finite')
        .refine((v) => v < 5, { error: (i) => `${String(i.input)} is not under 5` }),
    inputs: [1, 7],
  },
  {
    name: 'superRefine',
    build: (z) =>
      z.array(z.number()).superRefine((a, ctx) => {
        if (a.length % 2) ctx.addIssue({ code: 'custom', message: 'odd length', path: [a.length - 1] });
      }),
    inputs: [
      [1, 2],
      [1, 2, 3],
    ],
  },
  { name: 'schema params', build: (z) => z.number({ error: (i) => (i.input === undefined ? 'is missing' : 'must be a number') }), inputs: [undefined, 'x', 1] },
  {
    name: 'custom, never',
    build: (z) => z.object({ c: z.custom<{ p: number }>((v) => typeof v === 'object' && v !== null && 'p' in v, 'must have p'), n: z.never().optional() }),
    inputs: [{ c: { p: 1 } }, { c: {} }, { c: { p: 1 }, n: 1 }],
  },
  { name: 'pick', build: (z) => z.object({ a: z.number(), b: z.string() }).pick({ a: true }), inputs: [{ a: 1 }, { b: 'x' }] },
  // parseLightingScene's version 3 extends version 2's object (the browser's bake chunk threw "extend is not a function" without it).
  {
    name: 'extend',
    build: (z) => z.strictObject({ version: z.literal(2), a: z.number() }).extend({ version: z.literal(3), b: z.string().optional() }),
    inputs: [
      { version: 3, a: 1 },
      { version: 2, a: 1 },
      { version: 3, a: 1, b: 'x' },
      { version: 3, a: 1, c: 1 },
    ],
  },
];

describe('zod classic API on zod/mini (browser build) agrees with zod classic', () => {
  for (const c of cases) {
    it(c.name, () => {
      const a = c.build(classic);
      const b = c.build(mini as unknown as Z);
      for (const input of c.inputs) {
        const ra = a.safeParse(input);
        const rb = b.safeParse(input);
        expect(rb.success, `${c.name}: ${JSON.stringify(input)}`).toBe(ra.success);
        if (!ra.success) expect(rb.error!.issues.map((i) => [i.path, i.message])).toEqual(ra.error!.issues.map((i) => [i.path, i.message]));
        else expect(rb).toEqual(ra);
      }
    });
  }
});
