/**
 * The GLSL BVH traversal (shaders/bvhTraversal.glsl.ts) on a real WebGL2 context (headless-gl),
 * against a brute-force double-precision Möller–Trumbore over every triangle, and against the CPU
 * ray caster that walks the same textures. Scene: three boxes (one yawed, one yawed and scaled) and
 * a 2000-triangle random soup; 2400 seeded rays, half of them aimed at a random point of a random
 * triangle so that most of them hit something, one in eight along an axis, with finite and
 * unbounded tMax and unnormalised directions.
 */
import { describe, expect, it } from 'vitest';
import { bvhTraversal } from '../../../../shaders/bvhTraversal.glsl';
import { fragmentPass } from '../../../../shaders/fragmentPass.glsl';
import { createDataTexture } from '../../../../src/engines/bake/createDataTexture';
import { createFloatTarget, readRgba, requireFloatTargets } from '../../../../src/engines/bake/floatTarget';
import { createObjectRayCaster } from '../../../../src/engines/bake/objects/createObjectRayCaster';
import { prepareObjects } from '../../../../src/engines/bake/objects/prepareObjects';
import { passProgram, runPass } from '../../../../src/engines/bake/runPass';
import { createRng } from '../../../fuzz/mutate';
import { withHeadlessGL } from '../withHeadlessGL';
import { bruteForceClosest, sceneTriangles } from './bruteForceRays';
import { testScene } from './objectFixtures';

type V3 = [number, number, number];

const gl = withHeadlessGL();
const RAYS_X = 48;
const RAYS_Y = 50;
const RAY_COUNT = RAYS_X * RAYS_Y;

const objects = testScene();
const prepared = prepareObjects(objects, { texelSize: 0.05 });
const brute = sceneTriangles(objects);

/** Seeded rays from inside the 4 × 3 × 5 m room. */
function makeRays(): { origin: V3; dir: V3; tMax: number }[] {
  const rng = createRng(20261123);
  const rays: { origin: V3; dir: V3; tMax: number }[] = [];
  for (let r = 0; r < RAY_COUNT; r++) {
    const origin: V3 = [rng.next() * 4, rng.next() * 3, rng.next() * 5];
    let dir: V3;
    if (r % 8 === 7) {
      // Along an axis: two direction components exactly 0 (the safe inverse direction).
      const axis = rng.int(3);
      dir = [0, 0, 0];
      dir[axis] = (rng.chance(0.5) ? -1 : 1) * (0.5 + rng.next());
    } else if (r % 2 === 0) {
      // Aim at a random point of a random triangle.
      const k = rng.int(brute.count);
      let a = rng.next(),
        b = rng.next();
      if (a + b > 1) [a, b] = [1 - a, 1 - b];
      const P = brute.positions;
      const target = [0, 1, 2].map((i) => P[9 * k + i] + a * (P[9 * k + 3 + i] - P[9 * k + i]) + b * (P[9 * k + 6 + i] - P[9 * k + i]));
      dir = [target[0] - origin[0], target[1] - origin[1], target[2] - origin[2]];
    } else {
      const z = 2 * rng.next() - 1;
      const phi = 2 * Math.PI * rng.next();
      const s = Math.sqrt(1 - z * z);
      const scale = 0.2 + 3 * rng.next();
      dir = [scale * s * Math.cos(phi), scale * s * Math.sin(phi), scale * z];
    }
    // A third of the rays get a short tMax (shadow rays to a nearby lamp), the rest reach past the room.
    const tMax = r % 3 === 0 ? 0.2 + 1.5 * rng.next() : 1e4;
    rays.push({ origin: dir.every((x) => x === 0) ? [origin[0], origin[1], origin[2] + 1e-3] : origin, dir, tMax });
  }
  return rays;
}

const uniforms = { uNodes: 'sampler2D', uTriangles: 'sampler2D', uRays: 'sampler2D' } as const;
const pass = fragmentPass(
  uniforms,
  /* glsl */ `out vec4 outColor;
${bvhTraversal({ nodes: 'uNodes', triangles: 'uTriangles', width: prepared.bvh.width })}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(uRays, ivec2(2 * p.x, p.y), 0);
  vec4 b = texelFetch(uRays, ivec2(2 * p.x + 1, p.y), 0);
  float t;
  vec2 uv;
  bool front;
  bool hit = bvhClosestHit(a.xyz, b.xyz, a.w, t, uv, front);
  bool any = bvhAnyHit(a.xyz, b.xyz, a.w);
  outColor = vec4(hit ? t : -1.0, uv, (hit ? 1.0 : 0.0) + (front ? 2.0 : 0.0) + (any ? 4.0 : 0.0));
}
`,
);

function runOnGpu(rays: { origin: V3; dir: V3; tMax: number }[], bvh = prepared.bvh): Float32Array {
  const linear = requireFloatTargets(gl).linear;
  const data = new Float32Array(RAY_COUNT * 8);
  rays.forEach((ray, r) => {
    data.set([...ray.origin, ray.tMax, ...ray.dir, 0], 8 * r);
  });
  const rayTexture = createDataTexture(gl, data, 2 * RAYS_X, RAYS_Y, 4);
  const nodes = createDataTexture(gl, bvh.nodes, bvh.width, bvh.nodesHeight, 4);
  const triangles = createDataTexture(gl, bvh.triangles, bvh.width, bvh.trianglesHeight, 4);
  const target = createFloatTarget(gl, RAYS_X, RAYS_Y, linear);
  runPass(gl, passProgram(gl, pass), target, { uNodes: nodes, uTriangles: triangles, uRays: rayTexture });
  return readRgba(gl, target);
}

describe('bvhTraversal on WebGL2', () => {
  const rays = makeRays();
  const gpu = runOnGpu(rays);
  const caster = createObjectRayCaster(prepared);
  const reference = rays.map((ray) => bruteForceClosest(brute, ray.origin, ray.dir, ray.tMax));
  const clear = rays.map((_, r) => r).filter((r) => !reference[r].ambiguous);

  it('the scene is the one the brief asks for, and few rays are too close to call', () => {
    expect(prepared.triangleCount).toBe(brute.count);
    expect(brute.count).toBe(2036);
    expect(clear.length).toBeGreaterThan(0.97 * RAY_COUNT);
    expect(clear.length).toBeGreaterThanOrEqual(2000);
    // Enough of them hit, and enough miss or stop short.
    expect(clear.filter((r) => reference[r].hit).length).toBeGreaterThan(0.4 * RAY_COUNT);
    expect(clear.filter((r) => !reference[r].hit).length).toBeGreaterThan(0.1 * RAY_COUNT);
    expect(clear.filter((r) => r % 8 === 7 && reference[r].hit).length).toBeGreaterThan(30);
  });

  it('closest hit: t within 1e-4 relative and the face agree with brute force on every clear ray', () => {
    const wrong: string[] = [];
    for (const r of clear) {
      const ref = reference[r].hit;
      const hit = (gpu[4 * r + 3] & 1) === 1;
      const t = gpu[4 * r];
      const front = (gpu[4 * r + 3] & 2) === 2;
      if (!ref) {
        if (hit) wrong.push(`ray ${r}: GPU hit at t = ${t}, brute force misses`);
      } else if (!hit || Math.abs(t - ref.t) > 1e-4 * ref.t || front !== ref.frontFace) {
        wrong.push(`ray ${r}: GPU ${hit ? `t = ${t} front ${front}` : 'misses'}, brute force t = ${ref.t} front ${ref.frontFace}`);
      }
    }
    expect(wrong).toEqual([]);
  });

  it('any hit agrees with brute force on every clear ray', () => {
    const wrong = clear.filter((r) => ((gpu[4 * r + 3] & 4) === 4) !== (reference[r].hit !== null));
    expect(wrong).toEqual([]);
  });

  it('the CPU ray caster gives the brute-force answers, and the GPU atlas uv within 1e-5', () => {
    const wrong: string[] = [];
    let compared = 0;
    for (const r of clear) {
      const { origin, dir, tMax } = rays[r];
      const ref = reference[r].hit;
      const cpu = caster.closestHit(origin, dir, tMax);
      if (caster.anyHit(origin, dir, tMax) !== (ref !== null)) wrong.push(`ray ${r}: CPU any-hit disagrees`);
      if (!ref || !cpu) {
        if (ref || cpu) wrong.push(`ray ${r}: CPU ${cpu ? 'hits' : 'misses'}, brute force ${ref ? 'hits' : 'misses'}`);
        continue;
      }
      if (Math.abs(cpu.t - ref.t) > 1e-4 * ref.t || cpu.frontFace !== ref.frontFace) wrong.push(`ray ${r}: CPU t = ${cpu.t}, brute force ${ref.t}`);
      const du = Math.abs(gpu[4 * r + 1] - cpu.atlasUv[0]);
      const dv = Math.abs(gpu[4 * r + 2] - cpu.atlasUv[1]);
      if (du > 1e-5 || dv > 1e-5) wrong.push(`ray ${r}: GPU uv (${gpu[4 * r + 1]}, ${gpu[4 * r + 2]}), CPU (${cpu.atlasUv.join(', ')})`);
      compared++;
    }
    expect(wrong).toEqual([]);
    expect(compared).toBeGreaterThan(0.4 * RAY_COUNT);
  });

  it('an empty BVH (no objects) terminates and reports no hit', () => {
    const empty = runOnGpu(rays, prepareObjects([], { texelSize: 0.1 }).bvh);
    expect(Array.from({ length: RAY_COUNT }, (_, r) => empty[4 * r + 3]).every((flags) => flags === 0)).toBe(true);
  });
});
