import { describe, expect, it } from 'vitest';
import en from 'zod/v4/locales/en.js';
import type { $ZodRawIssue } from 'zod/v4/core';
import { z } from 'zod/mini';
import { safeParseInEnglish, zodEnglishError } from '../../src/core/zodEnglish';

const zods = en().localeError as (issue: $ZodRawIssue) => string;

// One issue for every branch of zod's English locale (zod/v4/locales/en.js), as zod's checks raise them.
const ISSUES = [
  { code: 'invalid_type', expected: 'number', input: 'x' },
  { code: 'invalid_type', expected: 'string', input: null },
  { code: 'invalid_type', expected: 'array', input: {} },
  { code: 'invalid_type', expected: 'object', input: [1] },
  { code: 'invalid_type', expected: 'number', input: Number.NaN },
  { code: 'invalid_type', expected: 'number', input: Number.POSITIVE_INFINITY },
  { code: 'invalid_type', expected: 'int', input: 1.5 },
  { code: 'invalid_type', expected: 'nan', input: 2 },
  { code: 'invalid_type', expected: 'string', input: undefined },
  { code: 'invalid_value', values: ['floor'], input: 'wall' },
  { code: 'invalid_value', values: [3], input: 4 },
  { code: 'invalid_value', values: ['floor', 'wall', 2, null], input: 'roof' },
  { code: 'too_big', origin: 'number', maximum: 10, inclusive: true, input: 11 },
  { code: 'too_big', origin: 'number', maximum: 10, inclusive: false, input: 10 },
  { code: 'too_big', origin: 'string', maximum: 80, inclusive: true, input: 'x' },
  { code: 'too_big', origin: 'array', maximum: 3, exact: true, input: [] },
  { code: 'too_big', origin: 'set', maximum: 2, inclusive: true, input: [] },
  { code: 'too_big', origin: 'map', maximum: 2, inclusive: true, input: [] },
  { code: 'too_big', origin: 'file', maximum: 2, inclusive: true, input: [] },
  { code: 'too_big', origin: 'bigint', maximum: 5n, inclusive: true, input: 6n },
  { code: 'too_big', maximum: 5, inclusive: true, input: 6 },
  { code: 'too_small', origin: 'number', minimum: 0, inclusive: false, input: 0 },
  { code: 'too_small', origin: 'number', minimum: 0.5, inclusive: true, input: 0 },
  { code: 'too_small', origin: 'string', minimum: 1, inclusive: true, input: '' },
  { code: 'too_small', origin: 'array', minimum: 2, exact: true, input: [] },
  { code: 'invalid_format', format: 'starts_with', prefix: 'lx-', input: 'a' },
  { code: 'invalid_format', format: 'ends_with', suffix: '.ies', input: 'a' },
  { code: 'invalid_format', format: 'includes', includes: '/', input: 'a' },
  { code: 'invalid_format', format: 'regex', pattern: /^#[0-9a-f]{6}$/i, input: 'a' },
  { code: 'invalid_format', format: 'url', input: 'a' },
  { code: 'invalid_format', format: 'template_literal', input: 'a' },
  { code: 'not_multiple_of', divisor: 0.5, input: 0.3 },
  { code: 'unrecognized_keys', keys: ['nearFeild'], input: {} },
  { code: 'unrecognized_keys', keys: ['a', 'b'], input: {} },
  { code: 'invalid_key', origin: 'record', issues: [], input: {} },
  { code: 'invalid_union', errors: [], input: 1 },
  { code: 'invalid_union', errors: [], options: ['floor', 'wall'], input: 1 },
  { code: 'invalid_union', errors: [], inclusive: false, input: 1 },
  { code: 'invalid_element', origin: 'map', key: 'k', issues: [], input: {} },
  { code: 'custom', input: 1 },
] as unknown as $ZodRawIssue[];

describe("zodEnglishError: zod's English sentences, cut to luxbox's formats", () => {
  it.each(ISSUES.map((issue) => [`${issue.code} ${JSON.stringify(issue, (_k, v) => (typeof v === 'bigint' ? `${v}n` : v instanceof RegExp ? String(v) : v))}`, issue] as const))('%s', (_name, issue) => {
    expect(zodEnglishError(issue)).toBe(zods(issue));
  });

  it('differs only in the names of string formats no luxbox schema checks', () => {
    const email = { code: 'invalid_format', format: 'email', input: 'a' } as unknown as $ZodRawIssue;
    expect(zods(email)).toBe('Invalid email address');
    expect(zodEnglishError(email)).toBe('Invalid email');
  });

  // This file loads no classic zod (whose index sets the English locale for every zod in the process).
  it('is what safeParseInEnglish words issues with; a bare mini parse has no sentences', () => {
    const atLeastZero = z.number().check(z.gte(0));
    expect(atLeastZero.safeParse(-1).error!.issues[0].message).toBe('Invalid input');
    expect(safeParseInEnglish(atLeastZero, -1).error!.issues[0].message).toBe('Too small: expected number to be >=0');
    expect(safeParseInEnglish(z.strictObject({ a: z.number() }), { a: 1, b: 2 }).error!.issues[0].message).toBe('Unrecognized key: "b"');
  });
});
