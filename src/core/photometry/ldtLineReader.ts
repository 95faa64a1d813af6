/** EULUMDAT's line-by-line part: one field per line, in order; an empty line is a field not given. */
import { checkRange } from './checks';
import { MAX_NUMERAL_LENGTH, readDecimal } from './decimal';
import { MAX_DIMENSION_M } from './limits';
import { excerpt, PhotometryParseError } from './PhotometryParseError';

/** Largest |dimension| in mm (luminaire and luminous area sizes). */
const MAX_DIMENSION_MM = MAX_DIMENSION_M * 1000;

export class LdtLineReader {
  /** The next line to read, 0-based (its line number is index + 1). */
  index = 0;

  constructor(
    readonly fileName: string,
    readonly lines: readonly string[],
  ) {}

  stringField(what: string): string {
    if (this.index >= this.lines.length) throw new PhotometryParseError(this.fileName, this.lines.length, `unexpected end of file: expected ${what}`);
    const t = this.lines[this.index++].trim();
    return t.length >= 2 && t.startsWith('"') && t.endsWith('"') ? t.slice(1, -1) : t;
  }
  /** A numeric line; empty → null when `optional` (the field is not given). */
  optionalNumber(what: string, optional: boolean): number | null {
    const line = this.index + 1;
    const raw = this.stringField(what);
    if (raw === '' && optional) return null;
    const read = readDecimal(raw);
    if (read.ok) return read.value;
    const problem =
      read.problem === 'not a number'
        ? `expected ${what} (a number${optional ? ' or an empty line' : ''}), found "${excerpt(raw)}"`
        : read.problem === 'too long'
          ? `${what}: a numeral of ${raw.length} characters is too long (limit ${MAX_NUMERAL_LENGTH})`
          : `${what} "${excerpt(raw)}" is out of range`;
    throw new PhotometryParseError(this.fileName, line, problem);
  }
  numberField(what: string): number {
    return this.optionalNumber(what, false) as number;
  }
  /** An optional numeric field: empty means "not given" (0 where a value is needed). */
  optionalField(what: string): number | null {
    return this.optionalNumber(what, true);
  }
  intField(what: string, min: number, max: number): number {
    const line = this.index + 1;
    const value = this.numberField(what);
    if (!Number.isInteger(value) || value < min) {
      throw new PhotometryParseError(this.fileName, line, `${what} must be an integer ≥ ${min}, found ${value}`);
    }
    if (value > max) throw new PhotometryParseError(this.fileName, line, `${what} ${value} exceeds the limit of ${max}`);
    return value;
  }
  /** A size in mm: empty is 0; within ±MAX_DIMENSION_MM. */
  dimension(what: string): number {
    const line = this.index + 1;
    const value = this.optionalField(what) ?? 0;
    checkRange(this.fileName, line, what, value, -MAX_DIMENSION_MM, MAX_DIMENSION_MM);
    return value;
  }
}
