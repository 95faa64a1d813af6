/**
 * Base class of every error caused by bad input (a malformed photometric file,
 * an impossible room, a corrupt scene). The CLI prints `message` as one line and
 * exits non-zero; the UI shows it. Anything that is not an InputError is a bug.
 */
export class InputError extends Error {
  override name = 'InputError';
  /** A stable code and its parameters, for UIs that show the message in another language (docs/i18n.md); absent for most errors. */
  readonly code?: string;
  readonly params?: Readonly<Record<string, string | number>>;
  constructor(message: string, coded?: { code: string; params?: Record<string, string | number> }) {
    super(message);
    if (coded) {
      this.code = coded.code;
      this.params = coded.params;
    }
  }
}
