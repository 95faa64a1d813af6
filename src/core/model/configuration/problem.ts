/**
 * A rule a configuration breaks, as validate() reports it (docs/model.md). Its own file so that the
 * domains that judge a configuration (rails, power, modules, objects, cues) and validation, which
 * gathers their problems, import it without importing each other.
 */
export interface Problem {
  /** Stable machine-readable code, e.g. 'outside-room'. */
  readonly code: string;
  /** One sentence for people (English: CLI, logs, the embedding API). */
  readonly message: string;
  /** The values in `message`, for UIs that word it in another language by `code` (docs/i18n.md); absent where none are given yet. */
  readonly params?: Readonly<Record<string, string | number>>;
  /** Where: e.g. 'systems[1].rails[0].modules[2].cct'. */
  readonly path: string;
}
