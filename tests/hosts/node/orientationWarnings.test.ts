/**
 * Issue #35 on the command line: a part whose inside cannot be told (three triangles of one part
 * on one edge; a closed part that passes through itself) is lit on both sides and said so in the
 * warnings `luxbox bake` prints on stderr and writes to report.json (sceneWarnings), with a line
 * for a closed part it turned outward; a clean model adds nothing.
 */
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { cliReadableFolders } from '../../../src/hosts/node/cliReadableFolders';
import { loadLightingSceneFileAsync } from '../../../src/hosts/node/loadLightingSceneFile';
import { sceneWarnings } from '../../../src/hosts/node/sceneWarnings';
import { insideOut, objText, pushedThroughBox, spineFanMesh, wedgeMesh } from '../../core/mesh/orientFixtures';

const folder = mkdtempSync(join(tmpdir(), 'luxbox-orient-'));
afterAll(() => rmSync(folder, { recursive: true, force: true }));

async function warningsFor(models: Record<string, string>): Promise<string[]> {
  for (const [name, text] of Object.entries(models)) writeFileSync(join(folder, name), text);
  // Raised 1 m: the fixtures reach below their origin (the fan to −0.87 m, the pushed-through box to −0.5 m).
  const objects = Object.keys(models).map((mesh, i) => ({ mesh, position: [1 + 1.5 * i, 1, 1.5] }));
  const scene = join(folder, 'scene.json');
  writeFileSync(
    scene,
    JSON.stringify({
      version: 2,
      room: { width: 6, height: 2.5, depth: 6, reflectance: { floor: 0.3, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
      luminaires: [{ photometry: join(process.cwd(), 'public/ies/bega_50975_downlight_lm1995_crlf.ies'), position: [3, 2.4, 3] }],
      objects,
    }),
  );
  const loaded = await loadLightingSceneFileAsync(scene, { within: cliReadableFolders(scene) });
  return sceneWarnings(loaded, scene);
}

describe('luxbox bake warnings about sides (sceneWarnings)', () => {
  it('a non-manifold part and a self-intersecting closed part: one line each that they are lit on both sides; an inside-out wedge: turned outward', async () => {
    const lines = await warningsFor({ 'fan.obj': objText(spineFanMesh()), 'pushed.obj': objText(pushedThroughBox(-0.5)), 'attic.obj': objText(insideOut(wedgeMesh(1, 1, 1))) });
    expect(lines).toContain('fan.obj: 1 part with no clear inside (faces that cannot be wound alike) lit on both sides');
    expect(lines).toContain('pushed.obj: 1 part with no clear inside (faces that cannot be wound alike) lit on both sides');
    expect(lines).toContain('attic.obj: 1 closed part faced inward and was turned outward (8 triangles reversed)');
  });

  it('the same box dented instead of pushed through: nothing to say', async () => {
    const lines = await warningsFor({ 'dented.obj': objText(pushedThroughBox(0.5)) });
    expect(lines.filter((l) => l.startsWith('dented.obj'))).toEqual([]);
  });
});
