import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { delimiter, join } from 'node:path';
import { NoWebGLError } from './createHeadlessGL';

const CHILD_FLAG = 'LUXBOX_UNDER_XVFB';

function onPath(program: string): boolean {
  return (process.env.PATH ?? '').split(delimiter).some((dir) => dir && existsSync(join(dir, program)));
}

/**
 * headless-gl needs an X display. With none set, re-run this very command
 * under `xvfb-run -a` and return its exit code; with one set, return null
 * (go on). Without xvfb-run, a clear one-line error.
 */
export function ensureDisplay(): number | null {
  if (process.env.DISPLAY || process.env[CHILD_FLAG]) return null;
  if (!onPath('xvfb-run')) {
    throw new NoWebGLError('no X display for headless WebGL: set DISPLAY or install xvfb (apt-get install xvfb) so luxbox can run itself under xvfb-run -a');
  }
  const result = spawnSync('xvfb-run', ['-a', process.execPath, ...process.execArgv, ...process.argv.slice(1)], {
    stdio: 'inherit',
    env: { ...process.env, [CHILD_FLAG]: '1' },
  });
  if (result.error) throw new NoWebGLError(`could not run xvfb-run: ${result.error.message}`);
  return result.status ?? 1;
}
