import { isDecimal, MAX_NUMERAL_LENGTH, readDecimal } from './decimal';
import { excerpt, PhotometryParseError } from './PhotometryParseError';

/** One token and the 1-based line it came from. */
export interface Token {
  text: string;
  line: number;
}

/**
 * Separators between values: white space (everything JavaScript's \s matches,
 * NBSP included — Latin-1 exports carry it), commas (lithonia-style lists),
 * semicolons, and the DOS end-of-file byte Ctrl-Z and NUL, which some
 * exporters leave at the end. Tested by code point, no regular expression.
 */
function isSeparator(c: number): boolean {
  if (c <= 0x20) return c === 0x20 || (c >= 0x09 && c <= 0x0d) || c === 0x1a || c === 0x00;
  if (c === 0x2c || c === 0x3b) return true; // , ;
  if (c < 0xa0) return false;
  return c === 0xa0 || c === 0x1680 || (c >= 0x2000 && c <= 0x200a) || c === 0x2028 || c === 0x2029 || c === 0x202f || c === 0x205f || c === 0x3000 || c === 0xfeff;
}

/** What is left after the data: how many tokens, how many numeric, the first few. */
export interface Leftovers {
  count: number;
  numeric: number;
  first: Token[];
}

/**
 * Reads the numeric part of a photometric file as a stream of numbers, in the
 * way LM-63 describes it: values separated by white space (or commas, which
 * real files use), lines breaking anywhere. Every value remembers its line so
 * errors can point at it. Tokens are scanned lazily, one pass over the text:
 * time and memory are linear in the input whatever it holds.
 */
export class NumberReader {
  private lineIndex = 0;
  private pos = 0;
  private peeked: Token | null = null;
  private last: Token | null = null;

  constructor(
    private readonly fileName: string,
    private readonly lines: readonly string[],
    private readonly firstLineNumber: number,
  ) {}

  /** The next token without consuming it, or null at the end of the data. */
  private peek(): Token | null {
    if (this.peeked) return this.peeked;
    while (this.lineIndex < this.lines.length) {
      const text = this.lines[this.lineIndex];
      while (this.pos < text.length && isSeparator(text.charCodeAt(this.pos))) this.pos++;
      if (this.pos < text.length) {
        const start = this.pos;
        while (this.pos < text.length && !isSeparator(text.charCodeAt(this.pos))) this.pos++;
        this.peeked = { text: text.slice(start, this.pos), line: this.firstLineNumber + this.lineIndex };
        return this.peeked;
      }
      this.lineIndex++;
      this.pos = 0;
    }
    return null;
  }

  private take(): Token | null {
    const token = this.peek();
    this.peeked = null;
    if (token) this.last = token;
    return token;
  }

  /** Line of the next token, or of the last token when the data ran out. */
  get line(): number {
    return this.peek()?.line ?? this.last?.line ?? 0;
  }

  /** Consumes everything left and reports it (trailing junk, leftover numbers). */
  leftovers(keep = 3): Leftovers {
    const result: Leftovers = { count: 0, numeric: 0, first: [] };
    for (let token = this.take(); token; token = this.take()) {
      result.count++;
      if (isDecimal(token.text)) result.numeric++;
      if (result.first.length < keep) result.first.push(token);
    }
    return result;
  }

  /**
   * The next number, which must be a finite decimal numeral. `what` names it
   * for the error message; `progress` lets a list reader say how far it got.
   */
  next(what: string, progress?: { expected: number; found: number; plural: string }): number {
    const token = this.take();
    if (!token) {
      const problem = progress ? `expected ${progress.expected} ${progress.plural}, found ${progress.found} (the file ends early)` : `unexpected end of file: expected ${what}`;
      throw new PhotometryParseError(this.fileName, this.last?.line ?? null, problem);
    }
    const read = readDecimal(token.text);
    if (read.ok) return read.value;
    const prefix = progress ? `expected ${progress.expected} ${progress.plural}, found ${progress.found}: ` : '';
    const shown = excerpt(token.text);
    const problem =
      read.problem === 'not a number'
        ? `${prefix}expected ${what}, found "${shown}"`
        : read.problem === 'too long'
          ? `${prefix}${what}: a numeral of ${token.text.length} characters is too long (limit ${MAX_NUMERAL_LENGTH})`
          : `${prefix}${what} "${shown}" is out of range`;
    throw new PhotometryParseError(this.fileName, token.line, problem);
  }

  /** Line of the token most recently returned by next(). */
  get lastLine(): number {
    return this.last ? this.last.line : this.line;
  }
}
