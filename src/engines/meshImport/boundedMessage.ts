import { InputError } from '../../core/inputError';
import { oneLine } from '../../core/untrustedJson';

/**
 * An importer's InputError as one line of at most 200 characters (the product's bound on every
 * message): the file's own name starts most messages, and a file may be named with 250 characters.
 * Anything else is rethrown unchanged (a bug stays a bug).
 */
export function boundedMessage(error: unknown): unknown {
  if (!(error instanceof InputError)) return error;
  const line = oneLine(error.message);
  return line === error.message ? error : new InputError(line);
}
