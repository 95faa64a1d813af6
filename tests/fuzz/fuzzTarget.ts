/**
 * One entry point under fuzz (issue 18): a parser the product exposes to
 * untrusted input. `run` must either return the accepted value's problems
 * (an empty list when the value is valid: finite, in range, no dropped field)
 * or throw the product's own input error with a one-line message. Anything
 * else — another exception, a non-finite number, a multi-line or overlong
 * message, a run slower than 1 s — is a failure found by the fuzzer.
 */
export interface FuzzSeed {
  /** File name of the real fixture the mutations start from (for the report). */
  name: string;
  bytes: Uint8Array;
}

export type FuzzOutcome = { kind: 'accepted'; problems: string[] } | { kind: 'refused'; message: string };

export interface FuzzTarget {
  /** Short name used in tables and `npm run fuzz -- --target <name>`. */
  name: string;
  /** Real fixtures (read from tests/fixtures, never from outside the repository). */
  seeds(): FuzzSeed[];
  /**
   * Feed one input. Returns `{kind:'accepted', problems}` when the entry point
   * accepted it (problems: what is wrong with the accepted value, [] if valid),
   * `{kind:'refused', message}` when it threw the product's input error.
   * Any other throw propagates and counts as a crash.
   */
  run(input: Uint8Array): FuzzOutcome;
}
