import { dirname, resolve } from 'node:path';
import { realFolders } from './readRegularFile';

/**
 * The folders whose files a scene given on the command line may name (docs/scene-format.md, "Which
 * files a scene may name"): the scene file's folder and the current folder, each with everything
 * below them, symbolic links resolved. A scene cannot make `luxbox` read `/dev/zero`, `/etc/…` or
 * a home directory's files by naming them; a file elsewhere is read when its path is given on the
 * command line itself (the scene file, a points or cameras file).
 */
export function cliReadableFolders(scenePath: string): string[] {
  return realFolders([dirname(resolve(scenePath)), process.cwd()]);
}
