import { InputError } from '../inputError';

/**
 * A photometric file that could not be read at all (missing, HTTP error, no
 * permission), as opposed to one that was read and is malformed
 * (PhotometryParseError). The message names the file: "ies/a.ies: HTTP 404".
 * `reason` alone lets a host phrase the message its users already know.
 */
export class PhotometryReadError extends InputError {
  override name = 'PhotometryReadError';
  readonly path: string;
  readonly reason: string;

  constructor(path: string, reason: string) {
    super(`${path}: ${reason}`);
    this.path = path;
    this.reason = reason;
  }
}
