import { InputError } from '../inputError';

/** Longest message a PhotometryParseError carries (one line, readable in a terminal or banner). */
export const MAX_MESSAGE_LENGTH = 200;

/**
 * A short, one-line quotation of file content for a message: control
 * characters and line breaks become spaces, and anything longer than `max`
 * characters is cut with "…" (a 100 000-digit numeral is never echoed back).
 */
export function excerpt(text: string, max = 24): string {
  const head = text.length > max ? text.slice(0, max) : text;
  // eslint-disable-next-line no-control-regex
  const clean = head.replace(/[\u0000-\u001f\u007f-\u009f\u2028\u2029]/g, ' ');
  return text.length > max ? clean + '…' : clean;
}

/**
 * A photometric file that cannot be read meaningfully. The message always names
 * the file and, where one applies, the line: "bega.ies line 12: expected 37
 * vertical angles, found 35". It is one line of at most MAX_MESSAGE_LENGTH
 * characters whatever the input (issue 18).
 */
export class PhotometryParseError extends InputError {
  override name = 'PhotometryParseError';
  readonly fileName: string;
  readonly line: number | null;

  constructor(fileName: string, line: number | null, problem: string) {
    const name = excerpt(fileName, 60);
    super(excerpt(line === null ? `${name}: ${problem}` : `${name} line ${line}: ${problem}`, MAX_MESSAGE_LENGTH - 1));
    this.fileName = fileName;
    this.line = line;
  }
}
