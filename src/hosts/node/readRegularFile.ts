import { closeSync, constants, fstatSync, openSync, readSync, realpathSync, type Stats } from 'node:fs';
import { sep } from 'node:path';
import { InputError } from '../../core/inputError';

/** Bytes read per system call. */
const CHUNK_BYTES = 1 << 16;

export interface ReadLimits {
  /** Most bytes the file may hold; checked while reading, not from stat alone (a device reports size 0). */
  maxBytes: number;
  /**
   * Folders (absolute) the file must lie in once symbolic links are resolved; absent: anywhere (a
   * path the user gave on the command line, or a trusted caller). The CLI's rule: docs/scene-format.md,
   * "Which files a scene may name".
   */
  within?: readonly string[];
}

/** What a file that is not a regular file is, in words. */
function kindOf(stats: Stats): string {
  if (stats.isDirectory()) return 'a directory';
  if (stats.isCharacterDevice()) return 'a character device';
  if (stats.isBlockDevice()) return 'a block device';
  if (stats.isFIFO()) return 'a named pipe';
  if (stats.isSocket()) return 'a socket';
  return 'not a plain file';
}

const megabytes = (bytes: number) => (bytes < 1e5 ? `${bytes} bytes` : `${Math.round(bytes / 1e5) / 10} MB`);
/** "1.4 MB; at most 1 MB", in bytes where megabytes would read the same (a file one byte over). */
function sizes(size: number, max: number): string {
  const [a, b] = [megabytes(size), megabytes(max)];
  return a === b ? `${size} bytes; at most ${max}` : `${a}; at most ${b}`;
}

function inside(file: string, folder: string): boolean {
  return file === folder || file.startsWith(folder.endsWith(sep) ? folder : folder + sep);
}

/** The real path of each folder (a folder that does not exist keeps its path: nothing can be inside it). */
export function realFolders(folders: readonly string[]): string[] {
  return folders.map((f) => {
    try {
      return realpathSync(f);
    } catch {
      return f;
    }
  });
}

/**
 * A file's bytes, read only if it is a regular file (issue 32: `/dev/zero` named as photometry, a
 * glTF buffer or an MTL library was read forever, since a character device reports size 0).
 * The path is resolved (symbolic links followed) and checked against `within`; the file is opened
 * non-blocking (opening a named pipe for reading would otherwise wait for a writer), fstat on the
 * open descriptor must say "regular file" (so nothing can be swapped in between the check and the
 * read), and it is read in chunks that stop one past `maxBytes`. Failures are an InputError whose
 * message is the reason alone ("no such file", "a character device, not a regular file", …): the
 * caller names the file.
 */
/**
 * A resolved path as the refusal quotes it: its last 40 characters. The caller already names the
 * file as the scene wrote it, and the message is one line of at most 200 characters, so a long
 * absolute path must not push the reason itself off its end.
 */
function pathTail(path: string): string {
  return path.length > 40 ? `…${path.slice(-39)}` : path;
}

export function readRegularFile(path: string, limits: ReadLimits): Uint8Array {
  let real: string;
  try {
    real = realpathSync(path);
  } catch (error) {
    const code = (error as NodeJS.ErrnoException).code;
    throw new InputError(code === 'ENOENT' ? 'no such file' : (code ?? 'read error'));
  }
  if (limits.within && !limits.within.some((folder) => inside(real, folder))) {
    throw new InputError(`${pathTail(real)} is outside the scene's folder (give more with --allow)`);
  }
  let fd: number;
  try {
    fd = openSync(real, constants.O_RDONLY | constants.O_NONBLOCK);
  } catch (error) {
    throw new InputError((error as NodeJS.ErrnoException).code ?? 'read error');
  }
  try {
    const stats = fstatSync(fd);
    if (!stats.isFile()) throw new InputError(`${kindOf(stats)}, not a regular file`);
    if (stats.size > limits.maxBytes) throw new InputError(`file is too large (${sizes(stats.size, limits.maxBytes)})`);
    const chunks: Uint8Array[] = [];
    let total = 0;
    for (;;) {
      // One byte more than allowed is enough to know the file is too large (it may grow while read).
      const chunk = new Uint8Array(Math.min(CHUNK_BYTES, limits.maxBytes + 1 - total));
      let n: number;
      try {
        n = readSync(fd, chunk, 0, chunk.length, null);
      } catch (error) {
        throw new InputError((error as NodeJS.ErrnoException).code ?? 'read error');
      }
      if (n === 0) break;
      chunks.push(n === chunk.length ? chunk : chunk.subarray(0, n));
      total += n;
      if (total > limits.maxBytes) throw new InputError(`file is too large (more than ${megabytes(limits.maxBytes)})`);
    }
    const out = new Uint8Array(total);
    let at = 0;
    for (const c of chunks) {
      out.set(c, at);
      at += c.length;
    }
    return out;
  } finally {
    closeSync(fd);
  }
}
