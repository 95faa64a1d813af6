import { InputError } from '../inputError';

/**
 * A photometric file that cannot be read meaningfully. The message always names
 * the file and, where one applies, the line: "bega.ies line 12: expected 37
 * vertical angles, found 35".
 */
export class PhotometryParseError extends InputError {
  override name = 'PhotometryParseError';
  readonly fileName: string;
  readonly line: number | null;

  constructor(fileName: string, line: number | null, problem: string) {
    super(line === null ? `${fileName}: ${problem}` : `${fileName} line ${line}: ${problem}`);
    this.fileName = fileName;
    this.line = line;
  }
}
