import { readFileSync, statSync } from 'node:fs';
import { basename, dirname, resolve } from 'node:path';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { LightingSceneError, parseLightingScene } from '../../core/model/parseLightingScene';
import type { LightingScene } from '../../core/model/lightingScene';
import { excerpt, INPUT_LIMITS, parseUntrustedJson } from '../../core/model/untrustedJson';
import { parsePhotometry } from '../../core/photometry/parsePhotometry';
import type { Photometry } from '../../core/photometry/types';

export interface LoadedLightingScene {
  scene: LightingScene;
  /** Parsed photometry per resolved path (each file read once, however many luminaires share it). */
  photometries: Map<string, Photometry>;
  /** Ready for the baker: photometry parsed, defaults filled in. */
  bakeScene: BakeScene;
}

/**
 * Parse JSON text under the shared input limits (size, syntax with line and
 * column, duplicate keys, nesting depth, array length), reporting problems as
 * one line `file: where: problem`.
 */
export function parseJsonText(text: string, source: string): unknown {
  return parseUntrustedJson(text, source, (message) => new LightingSceneError(message));
}

function readText(path: string, what: string): string {
  try {
    // Refuse a huge file before reading it (a mistaken argument: a video, a disk image).
    const size = statSync(path).size;
    if (size > INPUT_LIMITS.maxTextLength) {
      throw new LightingSceneError(`${what}: file is too large (${(size / 1e6).toFixed(1)} MB; at most ${INPUT_LIMITS.maxTextLength / 1e6} MB)`);
    }
    return readFileSync(path, 'utf8');
  } catch (error) {
    if (error instanceof LightingSceneError) throw error;
    const code = (error as NodeJS.ErrnoException).code ?? 'read error';
    throw new LightingSceneError(`${what}: cannot read ${path} (${code === 'ENOENT' ? 'no such file' : code})`);
  }
}

/**
 * Read a lighting scene file and every photometric file it names. Photometry
 * paths are relative to the scene file's folder (absolute paths are kept).
 */
export function loadLightingSceneFile(path: string): LoadedLightingScene {
  const source = basename(path);
  const scene = parseLightingScene(parseJsonText(readText(path, source), source), source);
  const folder = dirname(resolve(path));
  const photometries = new Map<string, Photometry>();
  const luminaires = scene.luminaires.map((l, i) => {
    const file = resolve(folder, l.photometry);
    let photometry = photometries.get(file);
    if (!photometry) {
      let data: Uint8Array;
      try {
        data = readFileSync(file);
      } catch (error) {
        const code = (error as NodeJS.ErrnoException).code;
        throw new LightingSceneError(`${source}: luminaires[${i}].photometry: cannot read ${excerpt(l.photometry)} (${code === 'ENOENT' ? 'no such file' : code ?? 'read error'})`);
      }
      photometry = parsePhotometry(data, file);
      photometries.set(file, photometry);
    }
    return { photometry, position: l.position, yaw: l.yaw, pitch: l.pitch, roll: l.roll, dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] };
  });
  const bakeScene: BakeScene = { room: scene.room, luminaires, ...(scene.nearField ? { nearField: scene.nearField } : {}) };
  return { scene, photometries, bakeScene };
}
