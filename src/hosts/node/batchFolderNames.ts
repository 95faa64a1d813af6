import { basename } from 'node:path';

/**
 * One output folder name per input file of a batch: the file name without
 * `.json` / `.luxbox.json`, made unique with -2, -3 … when two inputs share a
 * name (a/room.json, b/room.json → room, room-2).
 */
export function batchFolderNames(paths: string[]): string[] {
  const used = new Set<string>();
  return paths.map((p) => {
    const stem =
      basename(p)
        .replace(/(\.luxbox)?\.json$/i, '')
        .replace(/[^\w.-]+/g, '_') || 'scene';
    let name = stem;
    for (let k = 2; used.has(name); k++) name = `${stem}-${k}`;
    used.add(name);
    return name;
  });
}
