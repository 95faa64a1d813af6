import { readFileSync } from 'node:fs';
import { createPhotometryLoader } from '../../core/photometry/createPhotometryLoader';
import { PhotometryReadError } from '../../core/photometry/PhotometryReadError';
import type { Photometry } from '../../core/photometry/types';

/**
 * The Node host's photometry loader: files from the file system, synchronously
 * (the CLI loads, then bakes), keyed and named by the absolute path the caller
 * resolved, each read and parsed once per loader. A file that cannot be read is
 * a PhotometryReadError whose reason is 'no such file' or the system's code.
 */
export function createNodePhotometryLoader(): (file: string) => Photometry {
  return createPhotometryLoader((file: string): Uint8Array => {
    try {
      return readFileSync(file);
    } catch (error) {
      const code = (error as NodeJS.ErrnoException).code;
      throw new PhotometryReadError(file, code === 'ENOENT' ? 'no such file' : code ?? 'read error');
    }
  });
}
