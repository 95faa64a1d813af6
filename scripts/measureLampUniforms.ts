/**
 * Cost of one relighting direct basis with the lamps as constants (a program per position) and as
 * uniforms (settings.lampUniforms: a program per surface and photometry), docs/baker.md "Lamps as
 * uniforms": per scene and variant, in a fresh GL context, the first module's basis (compiles its
 * programs), then the same module moved by (0.3, 0, 0.2) m, then moved back and forth twice more
 * (the best of those three is reported as "moved"), then back at the first position (cached in
 * both variants: the pass alone), at the viewer's balanced quality with bounces 0.
 * Each time is the bake's wall time (start + read-back of the direct maps), compiles included (on
 * headless-gl they run synchronously inside startPrograms, so timings_ms.compile stays ~0), with
 * the number of programs the bake compiled (report shaders[].cached false). Before them, an untimed
 * bake without luminaires starts the context and prepares the objects.
 * Mesa keeps compiled shaders on disk across processes: disable that cache, or a scene measured
 * before looks compile-free. Run:
 *   MESA_SHADER_CACHE_DISABLE=true xvfb-run -a npx tsx scripts/measureLampUniforms.ts
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { livingRoom } from '../src/core/catalog/furnishedPresets';
import { serializeConfiguration } from '../src/core/model/files/sceneFile';
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
  const moved = (dx: number, dz: number) => module.map((l): BakeLuminaire => ({ ...l, position: [Math.min(width - 0.1, Math.max(0.1, l.position[0] + dx)), l.position[1], Math.min(depth - 0.1, Math.max(0.1, l.position[2] + dz))] }));
  // `--uniforms-first` swaps the order, to see that neither variant gains from running second.
  const order = process.argv.includes('--uniforms-first') ? [true, false] : [false, true];
  for (const lampUniforms of order) {
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
      return { ms, compiled: report.shaders.filter((s) => !s.cached).length };
    };
    // Untimed: the context's first bake and the objects' preparation (BVH, atlas; cached per object list).
    bake([]);
    const first = bake(module);
    const again = [bake(moved(0.3, 0.2)), bake(moved(-0.3, -0.2)), bake(moved(0.3, -0.2))];
    const best = again.reduce((a, b) => (b.ms < a.ms ? b : a));
    // Back at the first position: every program cached in both variants, so this is the pass itself.
    const same = bake(module);
    const fmt = (r: { ms: number; compiled: number }) => `${r.ms.toFixed(0)} ms (${r.compiled} programs compiled)`;
    console.log(`${label}, lamps as ${lampUniforms ? 'uniforms ' : 'constants'}: first ${fmt(first)}; moved ${fmt(best)}; back at the first position ${fmt(same)}`);
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
