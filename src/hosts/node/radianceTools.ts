import { execFileSync } from 'node:child_process';
import { chmodSync, existsSync, mkdirSync, readdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { LUMINANCE_WEIGHTS } from '../../engines/bake/bakedMaps';
import { WHITE_EFFICACY } from '../../engines/radiance/brightdataFile';
import type { ExportFile } from '../../engines/radiance/exportRadiance';

/**
 * Where Radiance's binaries are: $LUXBOX_RADIANCE_BIN, else the PyPI package pyradiance in the
 * project's .venv (scripts/setup.sh installs it), else `rtrace` on the PATH; null when none.
 */
export function findRadianceBin(root: string): string | null {
  if (process.env.LUXBOX_RADIANCE_BIN) return process.env.LUXBOX_RADIANCE_BIN;
  const lib = join(root, '.venv/lib');
  if (existsSync(lib)) {
    for (const python of readdirSync(lib)) {
      const bin = join(lib, python, 'site-packages/pyradiance/bin');
      if (existsSync(join(bin, 'rtrace'))) return bin;
    }
  }
  for (const dir of (process.env.PATH ?? '').split(':')) if (dir && existsSync(join(dir, 'rtrace'))) return dir;
  return null;
}

/** Write an export's files into `dir` (render.sh executable). */
export function writeExportFiles(dir: string, files: readonly ExportFile[]): void {
  for (const file of files) {
    const path = join(dir, file.path);
    mkdirSync(dirname(path), { recursive: true });
    writeFileSync(path, file.text);
    if (file.executable) chmodSync(path, 0o755);
  }
}

/** The environment Radiance's tools need: its binaries first on the PATH, "." and its library on RAYPATH. */
function radianceEnv(bin: string): NodeJS.ProcessEnv {
  const lib = join(bin, '../lib');
  return { ...process.env, PATH: `${bin}:${process.env.PATH ?? ''}`, RAYPATH: existsSync(lib) ? `.:${lib}` : (process.env.RAYPATH ?? '.') };
}

/** `oconv scene.rad > scene.oct` in an export folder. */
export function compileOctree(bin: string, dir: string): void {
  writeFileSync(join(dir, 'scene.oct'), execFileSync(join(bin, 'oconv'), ['scene.rad'], { cwd: dir, env: radianceEnv(bin) }));
}

/**
 * `rtrace -h -I <options> scene.oct` on "X Y Z dX dY dZ" lines: illuminance in lux per point
 * (179 lm/W and luxbox's luminance weights, as the export's render.sh computes it).
 */
export function rtraceLux(bin: string, dir: string, options: readonly string[], points: string): number[] {
  const out = execFileSync(join(bin, 'rtrace'), ['-h', '-I', ...options, 'scene.oct'], { cwd: dir, env: radianceEnv(bin), input: points, encoding: 'utf8', maxBuffer: 1 << 28 });
  return out
    .trim()
    .split('\n')
    .map((line) => line.trim().split(/\s+/).map(Number))
    .map(([r, g, b]) => WHITE_EFFICACY * (LUMINANCE_WEIGHTS[0] * r + LUMINANCE_WEIGHTS[1] * g + LUMINANCE_WEIGHTS[2] * b));
}
