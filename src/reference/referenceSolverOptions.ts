import { ReferenceInputError } from './referenceInputError';

/** The options both patch solvers take (solveRoomReference, solveFurnishedReference). */
export interface ReferenceSolverOptions {
  /** Edge of the patch lattice on every surface, metres (default 0.25). */
  patchSize?: number;
  /** Stop when the largest change of indirect illuminance in a sweep is below tolerance × the largest total (default 1e-6). */
  tolerance?: number;
  /** Give up (with an error) after this many Gauss–Seidel sweeps (default 10 000). */
  maxSweeps?: number;
}

/** The options with their defaults, each checked (a ReferenceInputError names the bad one). */
export function referenceSolverOptions(options: ReferenceSolverOptions): Required<ReferenceSolverOptions> {
  const patchSize = options.patchSize ?? 0.25;
  if (!(Number.isFinite(patchSize) && patchSize > 0)) throw new ReferenceInputError(`reference options: patchSize must be a finite length > 0 m, got ${patchSize}`);
  const tolerance = options.tolerance ?? 1e-6;
  if (!(tolerance > 0 && tolerance < 1)) throw new ReferenceInputError(`reference options: tolerance must be in (0, 1), got ${tolerance}`);
  const maxSweeps = options.maxSweeps ?? 10_000;
  if (!Number.isInteger(maxSweeps) || maxSweeps < 1) throw new ReferenceInputError(`reference options: maxSweeps must be an integer ≥ 1, got ${maxSweeps}`);
  return { patchSize, tolerance, maxSweeps };
}
