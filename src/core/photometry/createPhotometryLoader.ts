import { parsePhotometry } from './parsePhotometry';
import { PhotometryReadError } from './PhotometryReadError';
import type { Photometry } from './types';

/**
 * Reads and parses photometric files, each path once: a host passes how it
 * reads bytes (fetch in the browser, the file system in Node) and gets a cached
 * `load(path)`. The path is the cache key and the name the parser reports
 * (errors, warnings); each loader has its own cache.
 *
 * A reader may be asynchronous (the loader answers with promises; concurrent
 * loads of one path share one read) or synchronous (the loader answers at
 * once: the Node CLI loads and bakes without an event loop in between).
 *
 * Failures: a file that was read but does not parse stays cached as that
 * failure, so asking again gives the same error without reading again (the
 * bytes will not change their mind). A file that could not be read is not
 * cached: the next load tries again (the network may be back, the file may
 * now exist). Every read failure is a PhotometryReadError naming the path.
 */
export function createPhotometryLoader(readBytes: (path: string) => Promise<Uint8Array>): (path: string) => Promise<Photometry>;
export function createPhotometryLoader(readBytes: (path: string) => Uint8Array): (path: string) => Photometry;
export function createPhotometryLoader(readBytes: (path: string) => Uint8Array | Promise<Uint8Array>): (path: string) => Photometry | Promise<Photometry> {
  const cache = new Map<string, { value: Photometry | Promise<Photometry> } | { error: unknown }>();
  return (path) => {
    const hit = cache.get(path);
    if (hit) {
      if ('error' in hit) throw hit.error;
      return hit.value;
    }
    let bytes: Uint8Array | Promise<Uint8Array>;
    try {
      bytes = readBytes(path);
    } catch (error) {
      throw asReadError(path, error);
    }
    if (!(bytes instanceof Promise)) {
      try {
        const value = parsePhotometry(bytes, path);
        cache.set(path, { value });
        return value;
      } catch (error) {
        cache.set(path, { error });
        throw error;
      }
    }
    const value = bytes.then(
      (data) => parsePhotometry(data, path),
      (error: unknown) => {
        cache.delete(path);
        throw asReadError(path, error);
      },
    );
    cache.set(path, { value });
    return value;
  };
}

/** A reader's failure as a PhotometryReadError (a fetch TypeError or an fs error does not name the file). */
function asReadError(path: string, error: unknown): PhotometryReadError {
  if (error instanceof PhotometryReadError) return error;
  return new PhotometryReadError(path, error instanceof Error ? error.message : String(error));
}
