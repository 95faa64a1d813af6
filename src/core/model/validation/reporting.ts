/** What the validation rules share: the float tolerance, number formatting in sentences, and how a system's rules report. */

/** Float noise allowed at walls and grids (a nanometre). */
export const EPS = 1e-9;

/** A length in a sentence, to the millimetre. */
export function fmt(x: number): string {
  return String(Math.round(x * 1000) / 1000);
}

/** How a rule of a system reports a problem: code, path relative to the system, sentence, its params and sentence key (docs/i18n.md). */
export type ReportProblem = (code: string, path: string, message: string, params?: Record<string, string | number>, key?: string) => void;
