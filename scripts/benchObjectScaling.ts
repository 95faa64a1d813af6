/**
 * Bake cost against the objects' triangle count (issue #10: "with objects, cost grows with
 * log(triangles), not triangles"). One flat 1.6 × 0.9 m table top under a downlight, tessellated
 * into n × n × 2 triangles: coplanar, so the atlas stays one chart of the same size and only the
 * BVH grows. Same room, lamp and settings for every row; the first bake of each size warms the
 * shader cache and the prepared objects (the BVH is in textures, so every size compiles the same
 * sources); prepareObjects (charts, atlas, BVH build on the CPU) is timed on its own. Prints a markdown
 * table: `xvfb-run -a npx tsx scripts/benchObjectScaling.ts`. A benchmark, never a test.
 */
import { readFileSync } from 'node:fs';
import os from 'node:os';
import { parseIes } from '../src/core/photometry/parseIes';
import type { TriangleMesh } from '../src/core/mesh/triangleMesh';
import { createBaker } from '../src/engines/bake/createBaker';
import { prepareObjects } from '../src/engines/bake/objects/prepareObjects';
import type { BakeScene } from '../src/engines/bake/bakeScene';
import { createHeadlessGL } from '../src/hosts/node/createHeadlessGL';

function tessellatedTop(n: number): TriangleMesh {
  const positions = new Float32Array((n + 1) * (n + 1) * 3);
  for (let j = 0; j <= n; j++) {
    for (let i = 0; i <= n; i++) positions.set([-0.8 + (1.6 * i) / n, 0.75, -0.45 + (0.9 * j) / n], 3 * (j * (n + 1) + i));
  }
  const indices = new Uint32Array(n * n * 6);
  let k = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i;
      const b = a + 1;
      const c = a + n + 1;
      const d = c + 1;
      // Counterclockwise seen from above (+y): the lit side faces the lamp.
      indices.set([a, c, b, b, c, d], k);
      k += 6;
    }
  }
  return { positions, indices, materialOfTriangle: new Uint16Array(n * n * 2), materials: [{ name: 'top', reflectance: [0.5, 0.5, 0.5] }] };
}

const photometry = parseIes(readFileSync('public/ies/bega_50975_downlight_lm1995_crlf.ies', 'latin1'), 'bega_50975_downlight_lm1995_crlf.ies');
const room: BakeScene['room'] = { width: 4, height: 2.7, depth: 3.5, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } };
const luminaires: BakeScene['luminaires'] = [{ photometry, position: [2, 2.6, 1.75], yaw: 0, pitch: 0, roll: 0 }];
const settings = { texelSize: 0.1, samples: 32, bounces: 2 };

const gl = createHeadlessGL();
const baker = createBaker(gl);
const timeBake = (scene: BakeScene) => {
  const t0 = performance.now();
  baker.bake(scene, settings);
  return performance.now() - t0;
};
const rows: string[] = [];
const empty: BakeScene = { room, luminaires };
timeBake(empty);
rows.push(`| no objects | 0 | — | ${timeBake(empty).toFixed(0)} ms |`);
for (const n of [8, 32, 100, 316]) {
  const scene: BakeScene = { room, luminaires, objects: [{ id: 'top', mesh: tessellatedTop(n), position: [2, 0, 1.75], yaw: 0, scale: 1 }] };
  const p0 = performance.now();
  prepareObjects(scene.objects!, { texelSize: settings.texelSize });
  const prepare = performance.now() - p0;
  timeBake(scene);
  const runs = [timeBake(scene), timeBake(scene)].sort((a, b) => a - b);
  rows.push(`| table top ${n} × ${n} × 2 | ${2 * n * n} | ${prepare.toFixed(0)} ms | ${runs[0].toFixed(0)} ms |`);
}
baker.dispose();
gl.destroy();
console.log(
  `Run ${new Date().toISOString()}; ${os.cpus()[0]?.model ?? 'cpu'}, ${os.cpus().length} cores; texel ${settings.texelSize} m, ${settings.samples} samples, ${settings.bounces} bounces; GPU bake best of 2 after a warm-up bake per size (the objects are prepared once per list, so the timed bakes are the GPU passes; preparation timed on its own).\n`,
);
console.log('| scene | triangles | prepareObjects (CPU) | bake |\n|---|---|---|---|\n' + rows.join('\n'));
