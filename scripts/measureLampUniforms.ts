/**
 * Cost of one relighting direct basis with the lamps as constants (a program per position) and as
 * uniforms (settings.lampUniforms: a program per surface and photometry), docs/baker.md "Lamps as
 * uniforms": per scene and variant, in a fresh GL context, the first module's basis (compiles its
 * programs), then the same module moved by (0.3, 0, 0.2) m, then moved back and forth twice more
 * (the best of those three is reported as "moved"), at the viewer's balanced quality with bounces 0.
 * Each time is the bake's wall time (start + read-back of the direct maps); `compile` is the part
 * spent waiting for programs (the report's timings_ms.compile).
 * Run: xvfb-run -a npx tsx scripts/measureLampUniforms.ts
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { livingRoom } from '../src/core/catalog/furnishedPresets';
import { serializeConfiguration } from '../src/core/model/sceneFile';
import type { BakeLuminaire, BakeScene } from '../src/engines/bake/bakeScene';
import { resolveBakeSettings } from '../src/engines/bake/bakeSettings';
import { createBaker } from '../src/engines/bake/createBaker';
import { VIEWER_BAKE_SETTINGS } from '../src/engines/relight/createRelightEngine';
import { groupLuminaires } from '../src/engines/relight/luminaireGroups';
import { createHeadlessGL } from '../src/hosts/node/createHeadlessGL';
import { loadRenderInput } from '../src/hosts/node/renderInput';

function basis(scene: BakeScene, luminaires: BakeLuminaire[]): BakeScene {
  return { room: scene.room, luminaires, ...(scene.objects && scene.objects.length > 0 ? { objects: scene.objects } : {}) };
}

function measure(label: string, scene: BakeScene): void {
  const module = groupLuminaires(scene.luminaires)[0].basis;
  const { width, depth } = scene.room;
  const moved = (dx: number, dz: number) =>
    module.map((l): BakeLuminaire => ({ ...l, position: [Math.min(width - 0.1, Math.max(0.1, l.position[0] + dx)), l.position[1], Math.min(depth - 0.1, Math.max(0.1, l.position[2] + dz))] }));
  for (const lampUniforms of [false, true]) {
    const gl = createHeadlessGL();
    const baker = createBaker(gl);
    const settings = resolveBakeSettings({ ...VIEWER_BAKE_SETTINGS, bounces: 0, lampUniforms });
    const bake = (luminaires: BakeLuminaire[]) => {
      const t0 = performance.now();
      const job = baker.start(basis(scene, luminaires), settings);
      job.readDirect();
      const ms = performance.now() - t0;
      const report = job.report();
      job.dispose();
      return { ms, compile: report.timings_ms.compile, compiled: report.shaders.filter((s) => !s.cached).length };
    };
    const first = bake(module);
    const again = [bake(moved(0.3, 0.2)), bake(moved(-0.3, -0.2)), bake(moved(0.3, -0.2))];
    const best = again.reduce((a, b) => (b.ms < a.ms ? b : a));
    const fmt = (r: { ms: number; compile: number; compiled: number }) => `${r.ms.toFixed(0)} ms (compile ${r.compile.toFixed(0)} ms, ${r.compiled} programs compiled)`;
    console.log(`${label}, lamps as ${lampUniforms ? 'uniforms ' : 'constants'}: first ${fmt(first)}; moved ${fmt(best)}`);
    baker.dispose();
    gl.destroy();
  }
}

const cornerL = loadRenderInput(join(import.meta.dirname, '../tests/fixtures/configurations/corner-l.luxbox.json')).bakeScene;
const dir = mkdtempSync(join(tmpdir(), 'luxbox-lamp-uniforms-'));
const living = join(dir, 'living.luxbox.json');
writeFileSync(living, serializeConfiguration(livingRoom(defaultCatalog), defaultCatalog));
measure('corner-l (empty room)', cornerL);
measure('furnished living room', loadRenderInput(living).bakeScene);
