/**
 * zod's English messages for luxbox's schemas, and the one way luxbox parses with a schema.
 *
 * The schemas are written against `zod/mini` (docs/architecture.md, "Validation"): the same
 * validation core as classic zod, tree-shakeable, ~10 KiB gzip less of the first screen
 * (docs/benchmarks.md, "First screen"). Unlike classic, mini loads no locale, so an issue without a
 * message of the schema's own would read "Invalid input". `safeParseInEnglish` passes
 * `zodEnglishError` as the parse's error map (zod/v4/core/util.js `finalizeIssue`: a schema's or
 * check's own message first, then the parse's map, then the global config), so Node, Vitest, the
 * browser and a shop's bundle word every issue alike, without touching the global zod config a
 * shop's own schemas may use.
 *
 * `zodEnglishError` is zod's English locale (zod/v4/locales/en.js of zod 4.6.7) with the names of
 * string formats cut to those luxbox's schemas check (`url`; `regex` and the prefix checks have
 * sentences of their own): the other 30 names (email, UUID, IBAN, …) named formats no luxbox schema
 * has, and were first-screen bytes. Every sentence is zod's, character for character;
 * tests/core/zodEnglish.test.ts compares it with zod's own locale for each issue code.
 */
import { safeParse, util, type core } from 'zod/mini';

const SIZABLE: Record<string, string> = { string: 'characters', file: 'bytes', array: 'items', set: 'items', map: 'entries' };
const FORMAT_NAMES: Record<string, string> = { regex: 'input', url: 'URL', template_literal: 'input' };

function typeName(type: string, input?: unknown): string {
  if (type === 'number' && typeof input === 'number' && !Number.isFinite(input)) return String(input);
  return type === 'nan' ? 'NaN' : type;
}

type Issue = core.$ZodRawIssue & Record<string, never>;

/** zod's English sentence for an issue (the locale's `localeError`). */
export function zodEnglishError(raw: core.$ZodRawIssue): string {
  const issue = raw as Issue;
  switch (issue.code) {
    case 'invalid_type':
      return `Invalid input: expected ${typeName(issue.expected)}, received ${typeName(util.parsedType(issue.input), issue.input)}`;
    case 'invalid_value':
      if (issue.values.length === 1) return `Invalid input: expected ${util.stringifyPrimitive(issue.values[0])}`;
      return `Invalid option: expected one of ${util.joinValues(issue.values, '|')}`;
    case 'too_big': {
      const adj = issue.exact ? 'exactly ' : issue.inclusive ? '<=' : '<';
      const unit = SIZABLE[issue.origin];
      if (unit) return `Too big: expected ${issue.origin ?? 'value'} to have ${adj}${issue.maximum.toString()} ${unit}`;
      return `Too big: expected ${issue.origin ?? 'value'} to be ${adj}${issue.maximum.toString()}`;
    }
    case 'too_small': {
      const adj = issue.exact ? 'exactly ' : issue.inclusive ? '>=' : '>';
      const unit = SIZABLE[issue.origin];
      if (unit) return `Too small: expected ${issue.origin} to have ${adj}${issue.minimum.toString()} ${unit}`;
      return `Too small: expected ${issue.origin} to be ${adj}${issue.minimum.toString()}`;
    }
    case 'invalid_format':
      if (issue.format === 'starts_with') return `Invalid string: must start with "${issue.prefix}"`;
      if (issue.format === 'ends_with') return `Invalid string: must end with "${issue.suffix}"`;
      if (issue.format === 'includes') return `Invalid string: must include "${issue.includes}"`;
      if (issue.format === 'regex') return `Invalid string: must match pattern ${issue.pattern}`;
      return `Invalid ${FORMAT_NAMES[issue.format] ?? issue.format}`;
    case 'not_multiple_of':
      return `Invalid number: must be a multiple of ${issue.divisor}`;
    case 'unrecognized_keys':
      return `Unrecognized key${issue.keys.length > 1 ? 's' : ''}: ${util.joinValues(issue.keys, ', ')}`;
    case 'invalid_key':
      return `Invalid key in ${issue.origin}`;
    case 'invalid_union':
      if (Array.isArray(issue.options) && issue.options.length > 0) return `Invalid discriminator value. Expected ${(issue.options as unknown[]).map((o) => `'${String(o)}'`).join(' | ')}`;
      if (issue.inclusive === false) return 'Invalid input: more than one option matched';
      return 'Invalid input';
    case 'invalid_element':
      return `Invalid value in ${issue.origin}`;
    default:
      return 'Invalid input';
  }
}

/** `schema.safeParse(data)` with zod's English messages (zod/mini loads no locale: see above). */
export function safeParseInEnglish<S extends core.$ZodType>(schema: S, data: unknown): ReturnType<typeof safeParse<S>> {
  return safeParse(schema, data, { error: zodEnglishError });
}
