/**
 * Base class of every error caused by bad input (a malformed photometric file,
 * an impossible room, a corrupt scene). The CLI prints `message` as one line and
 * exits non-zero; the UI shows it. Anything that is not an InputError is a bug.
 */
export class InputError extends Error {
  override name = 'InputError';
  constructor(message: string) {
    super(message);
  }
}
