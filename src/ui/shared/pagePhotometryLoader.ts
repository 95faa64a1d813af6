import { PhotometryReadError } from '../../core/photometry/PhotometryReadError';
import type { Photometry } from '../../core/photometry/types';

/** Looks `fetch` up at call time, so a fetch a test or host installs later is the one used. */
const pageFetch: typeof fetch = (...args) => fetch(...args);

const loaders = new WeakMap<typeof fetch, Map<string, (path: string) => Promise<Photometry>>>();
/** Each photometry loader's companion for other files of the same folder (a catalog `model`'s L3D). */
const fileLoaders = new WeakMap<(path: string) => Promise<Photometry>, (path: string) => Promise<Uint8Array>>();

/**
 * The loader of raw files from the folder a page photometry loader reads (`baseUrl + path`), or
 * null for a loader made otherwise: the 3D view's bake feed loads catalog `model` files (L3D)
 * through it, so whoever hands the view its photometry loader hands it the asset folder too.
 */
export function pageFileLoaderOf(loadPhotometry: (path: string) => Promise<Photometry>): ((path: string) => Promise<Uint8Array>) | null {
  return fileLoaders.get(loadPhotometry) ?? null;
}

/**
 * The browser host's photometry loader: `load(path)` fetches `baseUrl + path`
 * (the catalog's paths are relative to the app's public folder; '' = relative
 * to the page) and parses it. One loader, so one cache, per page for each
 * folder: the plan's footprints and the 3D view ask for the same files and
 * each is fetched once between them. An HTTP error is "<path>: HTTP <status>".
 * The IES/LDT parsers load with the first file (a dynamic import): they are
 * not part of the page's first download (docs/benchmarks.md, "First screen").
 */
export function pagePhotometryLoader(baseUrl: string, fetchFn: typeof fetch = pageFetch): (path: string) => Promise<Photometry> {
  let byFolder = loaders.get(fetchFn);
  if (!byFolder) loaders.set(fetchFn, (byFolder = new Map()));
  const key = folderUrl(baseUrl);
  let load = byFolder.get(key);
  if (!load) {
    let parsing: Promise<(path: string) => Promise<Photometry>> | null = null;
    load = (path: string) => {
      parsing ??= import('../../core/photometry/createPhotometryLoader').then(
        ({ createPhotometryLoader }) =>
          createPhotometryLoader(async (file: string) => {
            const response = await fetchFn(baseUrl + file);
            if (!response.ok) throw new PhotometryReadError(file, `HTTP ${response.status}`);
            return new Uint8Array(await response.arrayBuffer());
          }),
        (error: unknown) => {
          // The parser chunk did not arrive (offline, deploy in between): the next load tries again.
          parsing = null;
          throw error;
        },
      );
      return parsing.then((loader) => loader(path));
    };
    byFolder.set(key, load);
    fileLoaders.set(load, async (path: string) => {
      const response = await fetchFn(baseUrl + path);
      if (!response.ok) throw new Error(`${path}: HTTP ${response.status}`);
      return new Uint8Array(await response.arrayBuffer());
    });
  }
  return load;
}

/** The folder as an absolute URL where there is a page, so '' and '/' share a cache when the page is at the site root. */
function folderUrl(baseUrl: string): string {
  return typeof document === 'undefined' ? baseUrl : new URL(baseUrl || './', document.baseURI).href;
}
