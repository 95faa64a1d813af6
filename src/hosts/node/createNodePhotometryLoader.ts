import { InputError } from '../../core/inputError';
import { createPhotometryLoader } from '../../core/photometry/createPhotometryLoader';
import { MAX_PHOTOMETRY_BYTES } from '../../core/photometry/limits';
import { PhotometryReadError } from '../../core/photometry/PhotometryReadError';
import type { Photometry } from '../../core/photometry/types';
import { readRegularFile } from './readRegularFile';

/**
 * The Node host's photometry loader: files from the file system, synchronously
 * (the CLI loads, then bakes), keyed and named by the absolute path the caller
 * resolved, each read and parsed once per loader. Only regular files of at most
 * MAX_PHOTOMETRY_BYTES are read, inside `within` when given (readRegularFile). A
 * file that cannot be read is a PhotometryReadError whose reason is 'no such
 * file', 'a character device, not a regular file', … or the system's code.
 */
export function createNodePhotometryLoader(options: { within?: readonly string[] } = {}): (file: string) => Photometry {
  return createPhotometryLoader((file: string): Uint8Array => {
    try {
      return readRegularFile(file, { maxBytes: MAX_PHOTOMETRY_BYTES, within: options.within });
    } catch (error) {
      if (error instanceof InputError) throw new PhotometryReadError(file, error.message);
      throw error;
    }
  });
}
