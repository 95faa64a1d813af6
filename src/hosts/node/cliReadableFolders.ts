import { delimiter, dirname, resolve } from 'node:path';
import { realFolders } from './readRegularFile';
import { PUBLIC_DIR } from './renderInput';

/** The option that names more folders a scene's files may lie in (several joined like PATH: `a:b`). */
export const ALLOW_FLAG = '--allow';

/**
 * The folders whose files a scene given on the command line may name (docs/scene-format.md, "Which
 * files a scene may name"; issue 32): the scene file's folder, luxbox's own public folder (the
 * photometry it ships, PUBLIC_DIR) and the folders given with `--allow` on the command line, each
 * with everything below it, symbolic links resolved. Not the current folder: run from a home
 * directory, a downloaded scene naming `../.ssh/…` could otherwise make `luxbox` read it and quote
 * a line of it in its error message. A file elsewhere is read when its own path is given on the
 * command line (the scene file, a points or cameras file).
 */
export function cliReadableFolders(scenePath: string, allow?: string): string[] {
  const given = allow ? allow.split(delimiter).filter((f) => f !== '') : [];
  return realFolders([dirname(resolve(scenePath)), PUBLIC_DIR, ...given.map((f) => resolve(f))]);
}
