/** A relative error as the bench tables write it: percent with two decimals. */
export const percentCell = (e: number): string => `${(100 * e).toFixed(2)} %`;

/**
 * The first table of a bench section whose scenes are checked against the radiosity reference
 * (docs/benchmarks.md, "Rooms of any shape" and "Daylight"): each scene's name and description,
 * the reference's patch count and its time (solve + queries), then a blank line.
 */
export function referenceSceneTable(parts: readonly { scene: { name: string; description: string }; patches: number; referenceMs: number }[]): string[] {
  return ['| scene | reference patches | reference time (solve + queries) |', '|---|---|---|', ...parts.map((p) => `| ${p.scene.name}: ${p.scene.description} | ${p.patches} | ${(p.referenceMs / 1000).toFixed(1)} s |`), ''];
}
