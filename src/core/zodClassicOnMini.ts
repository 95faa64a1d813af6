/**
 * The part of zod 4's "classic" API luxbox uses, on top of `zod/mini` (the same
 * validation core, tree-shakeable): the browser build resolves `zod` to this
 * module (vite.config.ts), because classic ships every schema type and method
 * (~21 KiB gzip of the first download; docs/benchmarks.md, "First screen").
 * Node (CLI, tests) uses zod classic itself; types always come from classic.
 *
 * Each classic method is what classic does, spelled with mini's functions:
 * `.min(n)` is `check(gte(n))` on numbers and `check(minLength(n))` on strings
 * and arrays, `.int()` checks the integer format, `.optional()` wraps, and so
 * on (zod/v4/classic/schemas.js). Messages are zod's English ones (the locale
 * classic loads by default, cut to what luxbox's schemas can say: zodEnglish.ts). A method luxbox does not use is not here: calling
 * one fails loudly in the browser build and its tests (tests/core/zodClassicOnMini.test.ts).
 */
import {
  array,
  boolean,
  config,
  custom,
  discriminatedUnion,
  enum as zEnum,
  extend,
  gt,
  gte,
  int,
  literal,
  lt,
  lte,
  maxLength,
  minLength,
  never,
  nullable,
  number,
  object,
  optional,
  pick,
  record,
  refine,
  regex,
  strictObject,
  string,
  superRefine,
  tuple,
  union,
  url,
  type ZodMiniObject,
  type ZodMiniType,
} from 'zod/mini';
import { zodEnglishError } from './zodEnglish';

// zod's English messages, without the names of string formats no luxbox schema has (zodEnglish.ts).
config({ localeError: zodEnglishError });

/** Classic's per-check params (`'message'` or `{ error, message, abort }`), passed on untouched. */
type Params = string | { error?: unknown; message?: string; abort?: boolean };
type Schema = ZodMiniType & Record<string, unknown>;
type Check = Parameters<ZodMiniType['check']>[0];

const isLength = (s: Schema) => {
  const type = s._zod.def.type;
  return type === 'string' || type === 'array';
};

/** Give a mini schema classic's chainable methods (each returns a new schema with them too). */
function classic<T extends ZodMiniType>(schema: T): T {
  const s = schema as unknown as Schema;
  const check = (c: unknown) => classic(s.check(c as Check));
  Object.assign(s, {
    optional: () => classic(optional(s)),
    nullable: () => classic(nullable(s)),
    array: () => classic(array(s)),
    min: (n: number, p?: Params) => check(isLength(s) ? minLength(n, p as never) : gte(n, p as never)),
    max: (n: number, p?: Params) => check(isLength(s) ? maxLength(n, p as never) : lte(n, p as never)),
    gt: (n: number, p?: Params) => check(gt(n, p as never)),
    gte: (n: number, p?: Params) => check(gte(n, p as never)),
    lt: (n: number, p?: Params) => check(lt(n, p as never)),
    lte: (n: number, p?: Params) => check(lte(n, p as never)),
    positive: (p?: Params) => check(gt(0, p as never)),
    nonnegative: (p?: Params) => check(gte(0, p as never)),
    int: (p?: Params) => check(int(p as never)),
    // zod 4 numbers are finite already; classic's .finite() is a no-op kept for zod 3 code.
    finite: () => s,
    regex: (re: RegExp, p?: Params) => check(regex(re, p as never)),
    url: (p?: Params) => check(url(p as never)),
    refine: (fn: (v: unknown) => unknown, p?: Parameters<typeof refine>[1]) => check(refine(fn, p)),
    superRefine: (fn: Parameters<typeof superRefine>[0]) => check(superRefine(fn)),
    pick: (mask: Record<string, true>) => classic(pick(s as unknown as ZodMiniObject, mask)),
    extend: (shape: Record<string, ZodMiniType>) => classic(extend(s as unknown as ZodMiniObject, shape)),
  });
  return schema;
}

type Fn = (...args: never[]) => ZodMiniType;
const wrap =
  <F extends Fn>(f: F) =>
  (...args: Parameters<F>): ReturnType<F> =>
    classic(f(...args) as ReturnType<F>);

/** `z` as luxbox imports it (`import { z } from 'zod'`). */
export const z = {
  string: wrap(string),
  number: wrap(number),
  boolean: wrap(boolean),
  literal: wrap(literal),
  enum: wrap(zEnum),
  never: wrap(never),
  custom: wrap(custom),
  array: wrap(array),
  tuple: wrap(tuple),
  union: wrap(union),
  discriminatedUnion: wrap(discriminatedUnion),
  record: wrap(record),
  object: wrap(object),
  strictObject: wrap(strictObject),
  optional: wrap(optional),
  nullable: wrap(nullable),
};

export default z;
