import { PhotometryParseError } from './PhotometryParseError';

/** One number token and the 1-based line it came from. */
interface Token {
  text: string;
  line: number;
}

// A plain decimal number as photometric files write it: "12", "-0.5", ".625",
// "5000.", "1.2E+03". Deliberately not Number(): that would accept "0x1F",
// "Infinity" and "" (as 0), all of which would be silent nonsense here.
// White space, commas (lithonia-style lists), semicolons, and the DOS
// end-of-file byte Ctrl-Z and NUL, which some exporters leave at the end.
const SEPARATORS = /[\s,;]+/;
const CTRL_Z = String.fromCharCode(0x1a);
const NUL = String.fromCharCode(0);

const NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;

/**
 * Reads the numeric part of a photometric file as a stream of numbers, in the
 * way LM-63 describes it: values separated by white space (or commas, which
 * real files use), lines breaking anywhere. Every value remembers its line so
 * errors can point at it.
 */
export class NumberReader {
  private readonly tokens: Token[] = [];
  private index = 0;

  constructor(
    private readonly fileName: string,
    lines: readonly string[],
    firstLineNumber: number,
  ) {
    lines.forEach((text, i) => {
      const cleaned = text.replaceAll(CTRL_Z, ' ').replaceAll(NUL, ' ');
      for (const part of cleaned.split(SEPARATORS)) {
        if (part !== '') this.tokens.push({ text: part, line: firstLineNumber + i });
      }
    });
  }

  /** Line of the next token, or of the last token when the data ran out. */
  get line(): number {
    const token = this.tokens[Math.min(this.index, this.tokens.length - 1)];
    return token ? token.line : 0;
  }

  get remaining(): number {
    return this.tokens.length - this.index;
  }

  /** The tokens not consumed yet (trailing junk, leftovers). */
  rest(): Token[] {
    return this.tokens.slice(this.index);
  }

  /**
   * The next number, which must be finite. `what` names it for the error
   * message; `found`/`expected` let a list reader say how far it got.
   */
  next(what: string, progress?: { expected: number; found: number; plural: string }): number {
    const token = this.tokens[this.index];
    if (!token) {
      const lastLine = this.tokens.length ? this.tokens[this.tokens.length - 1].line : null;
      const problem = progress
        ? `expected ${progress.expected} ${progress.plural}, found ${progress.found} (the file ends early)`
        : `unexpected end of file: expected ${what}`;
      throw new PhotometryParseError(this.fileName, lastLine, problem);
    }
    this.index++;
    if (!NUMBER.test(token.text)) {
      const shown = token.text.length > 24 ? token.text.slice(0, 24) + '…' : token.text;
      const prefix = progress ? `expected ${progress.expected} ${progress.plural}, found ${progress.found}: ` : '';
      throw new PhotometryParseError(this.fileName, token.line, `${prefix}expected ${what}, found "${shown}"`);
    }
    const value = Number(token.text);
    if (!Number.isFinite(value)) {
      throw new PhotometryParseError(this.fileName, token.line, `${what} "${token.text}" is out of range`);
    }
    return value;
  }

  /** Line of the token most recently returned by next(). */
  get lastLine(): number {
    const token = this.tokens[this.index - 1];
    return token ? token.line : this.line;
  }
}
