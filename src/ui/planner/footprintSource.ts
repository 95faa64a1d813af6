import { photometryWarnings } from '../../core/photometry/checks';
import type { Photometry } from '../../core/photometry/types';
import { pageFileLoaderOf, pagePhotometryLoader } from '../shared/pagePhotometryLoader';
import { floorFootprint, type FloorFootprint } from './floorFootprint';

/**
 * Loads each photometric file the plan needs once (the page's photometry loader, shared with
 * the 3D view, then floorFootprint) and tells subscribers when one arrives. The plan draws a module's measured footprint when it is
 * loaded, and the catalog beam-angle cone before that or if the file cannot be loaded.
 */
export interface FootprintSource {
  /** The footprint for a catalog photometry path: undefined while loading, null if unavailable. */
  get(path: string): FloorFootprint | null | undefined;
  /**
   * The file's non-fatal findings (photometryWarnings: 360° plane ≠ 0° plane, stated vs
   * integrated lumens, …), one line each without the file name; empty while loading or
   * when the file could not be read.
   */
  warnings(path: string): readonly string[];
  /** Starts loading paths not seen before. */
  request(paths: readonly string[]): void;
  subscribe(listener: () => void): () => void;
  /** Increases whenever a file finished (for useSyncExternalStore snapshots). */
  version(): number;
  /** The page's photometry loader for the same folder (the 3D view loads through it: one fetch per file for both). */
  loadPhotometry(path: string): Promise<Photometry>;
  /**
   * The plan outline of a catalog `model` (L3D): the body's convex hull from above, [x, z] metres
   * about the photometric centre, x along the rail (l3dPlanOutline); undefined while loading,
   * null if unavailable (the module's rectangle stands in).
   */
  outline(path: string): readonly [number, number][] | null | undefined;
  /** Starts loading the outlines of model paths not seen before. */
  requestOutlines(paths: readonly string[]): void;
}

export function createFootprintSource(baseUrl: string, fetchFn?: typeof fetch): FootprintSource {
  const loadPhotometry = pagePhotometryLoader(baseUrl, fetchFn);
  const results = new Map<string, FloorFootprint | null>();
  const warnings = new Map<string, readonly string[]>();
  const pending = new Set<string>();
  const listeners = new Set<() => void>();
  let version = 0;
  const outlines = new Map<string, readonly [number, number][] | null>();
  const pendingOutlines = new Set<string>();
  const loadFile = pageFileLoaderOf(loadPhotometry);
  const done = (path: string, value: FloorFootprint | null) => {
    pending.delete(path);
    results.set(path, value);
    version++;
    for (const l of [...listeners]) l();
  };
  const outlineDone = (path: string, value: readonly [number, number][] | null) => {
    outlines.set(path, value);
    version++;
    for (const l of [...listeners]) l();
  };
  return {
    loadPhotometry,
    outline: (path) => outlines.get(path),
    requestOutlines(paths) {
      for (const path of paths) {
        if (outlines.has(path) || pendingOutlines.has(path)) continue;
        if (!loadFile) {
          outlineDone(path, null);
          continue;
        }
        pendingOutlines.add(path);
        Promise.all([loadFile(path), import('./modelOutline')])
          .then(([bytes, { modelOutline }]) => outlineDone(path, modelOutline(bytes, path)))
          .catch((e: unknown) => {
            console.warn('luxbox: no plan outline for', path, e);
            outlineDone(path, null);
          })
          .finally(() => pendingOutlines.delete(path));
      }
    },
    get: (path) => results.get(path),
    warnings: (path) => warnings.get(path) ?? [],
    request(paths) {
      for (const path of paths) {
        if (results.has(path) || pending.has(path)) continue;
        pending.add(path);
        loadPhotometry(path)
          .then((ph) => {
            warnings.set(path, photometryWarnings(ph));
            done(path, floorFootprint(ph));
          })
          .catch((e: unknown) => {
            // The cone from the catalog's beam angle stands in; the 3D view reports file problems.
            console.warn('luxbox: no measured footprint for', path, e);
            done(path, null);
          });
      }
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    version: () => version,
  };
}
