import { dirname, resolve } from 'node:path';
import { photometryWarnings } from '../../core/photometry';
import type { LoadedLightingScene } from './loadLightingSceneFile';
import { orientationNotes } from '../../engines/meshImport/orientationNotes';

/** A photometry path as it appears in a warning: as written in the scene, at most 60 characters (the end kept). */
function shownName(path: string): string {
  const flat = path.replace(/[\r\n\t\u2028\u2029]+/g, ' ');
  return flat.length > 60 ? `…${flat.slice(-59)}` : flat;
}

/**
 * The photometry warnings of a loaded scene (docs/photometry.md, "Warnings"),
 * one line each, `<file>: <warning>`, the file named as the scene names it;
 * each file once, in the order the luminaires first use it; then the mesh
 * import warnings and orientation notes (docs/scene-format.md, "Objects",
 * docs/furniture.md; they name their file), each mesh once, in the order the objects first use it. For report.json's
 * `warnings` and the CLI's stderr.
 */
export function sceneWarnings(loaded: LoadedLightingScene, scenePath: string): string[] {
  const folder = dirname(resolve(scenePath));
  const seen = new Set<string>();
  const lines: string[] = [];
  for (const l of loaded.scene.luminaires) {
    const file = resolve(folder, l.photometry);
    if (seen.has(file)) continue;
    seen.add(file);
    const ph = loaded.photometries.get(file);
    if (!ph) continue;
    for (const w of photometryWarnings(ph)) lines.push(`${shownName(l.photometry)}: ${w}`);
  }
  for (const imported of loaded.meshes.values()) lines.push(...imported.warnings, ...orientationNotes(imported.name, imported.orientation));
  return lines;
}
