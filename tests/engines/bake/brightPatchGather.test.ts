/**
 * The one bright-patch loop (shaders/brightPatchGather.glsl.ts) run on headless-gl for chosen
 * receivers, against analytic form factors: a 0.1 × 0.1 m patch on the ceiling (facing down) and
 * receivers below it at 0.5 m (contour integral) and 2 m (40 half edges: point form factor).
 *
 * Reference: the on-axis form factor of a differential area parallel to a rectangle, four times
 * Howell's corner case B-3, F = (1/2π)[A/√(1+A²)·atan(B/√(1+A²)) + B/√(1+B²)·atan(A/√(1+B²))],
 * A = a/c, B = b/c (Howell, "A Catalog of Radiation Heat Transfer Configuration Factors"); off
 * axis at 40 half edges, the point form factor A·cosθ_r·cosθ_e/(π d²), to 2e-3 relative (its
 * error there is O((size/d)²) ≈ 1e-3).
 *
 * The receiver cosine: a receiver facing away from the patch gets exactly 0 in both the near field
 * (the rectangle clipped away) and the far field (max(cos θ_r, 0)); with |cos θ_r| the far-field
 * receivers turned away would get the value of the ones turned toward it, and these cases fail.
 */
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { brightPatchGather } from '../../../shaders/brightPatchGather.glsl';
import { fragmentPass } from '../../../shaders/fragmentPass.glsl';
import { createDataTexture } from '../../../src/engines/bake/createDataTexture';
import { createFloatTarget, deleteTarget, readRgba, requireFloatTargets } from '../../../src/engines/bake/floatTarget';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { PATCH_TABLE_WIDTH } from '../../../src/engines/bake/patchTable';
import { passProgram, runPass } from '../../../src/engines/bake/runPass';
import { boxMesh, placed } from './objects/objectFixtures';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
requireFloatTargets(gl);

const HALF = 0.05;
const CENTRE: Vec3 = [1, 2, 1];
const CEILING = 1;
const EXITANCE: Vec3 = [1000, 500, 250];
const AREA = 4 * HALF * HALF;

/** Howell B-3 four times: on the axis of the patch, parallel, at distance c. */
function onAxis(c: number): number {
  const A = HALF / c;
  const corner = (A / Math.sqrt(1 + A * A)) * Math.atan(A / Math.sqrt(1 + A * A)) * 2;
  return (4 * corner) / (2 * Math.PI);
}

/** The point form factor from p (unit normal n) to the patch, cos θ_r clamped at 0. */
function pointFormFactor(p: Vec3, n: Vec3): number {
  const d: Vec3 = [CENTRE[0] - p[0], CENTRE[1] - p[1], CENTRE[2] - p[2]];
  const d2 = d[0] ** 2 + d[1] ** 2 + d[2] ** 2;
  const cosR = Math.max((n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.sqrt(d2), 0);
  const cosE = d[1] / Math.sqrt(d2);
  return (AREA * cosR * cosE) / (Math.PI * d2);
}

const deg = Math.PI / 180;
const tilted = (angle: number): Vec3 => [Math.sin(angle * deg), Math.cos(angle * deg), 0];

interface Receiver {
  name: string;
  p: Vec3;
  n: Vec3;
  /** Form factor to the patch with nothing in between. */
  expected: number;
  tolerance: number;
}

const RECEIVERS: Receiver[] = [
  { name: 'near, facing', p: [1, 1.5, 1], n: [0, 1, 0], expected: onAxis(0.5), tolerance: 1e-4 },
  { name: 'far, facing', p: [1, 0, 1], n: [0, 1, 0], expected: onAxis(2), tolerance: 2e-3 },
  { name: 'near, facing away', p: [1, 1.5, 1], n: [0, -1, 0], expected: 0, tolerance: 0 },
  { name: 'far, facing away', p: [1, 0, 1], n: [0, -1, 0], expected: 0, tolerance: 0 },
  { name: 'far, tilted 60° toward', p: [1.3, 0, 0.8], n: tilted(60), expected: pointFormFactor([1.3, 0, 0.8], tilted(60)), tolerance: 2e-3 },
  { name: 'far, tilted 120° (away)', p: [1.3, 0, 0.8], n: tilted(120), expected: 0, tolerance: 0 },
  { name: 'far, edge-on from below the horizon', p: [0.2, 0, 1], n: [-1, 0, 0], expected: 0, tolerance: 0 },
];

function patchTexture(): WebGLTexture {
  const row = new Float32Array(PATCH_TABLE_WIDTH * 4);
  row.set([...CENTRE, CEILING, HALF, 0, 0, 0, 0, 0, HALF, 0, ...EXITANCE, 0]);
  return createDataTexture(gl, row, PATCH_TABLE_WIDTH, 1, 4);
}

/** E at each receiver (one texel each) from the one patch, through the chunk with or without occlusion. */
function irradiance(occluder: Vec3 | null, receiverSurface = -1): Float32Array {
  const points = new Float32Array(RECEIVERS.length * 4);
  const normals = new Float32Array(RECEIVERS.length * 4);
  RECEIVERS.forEach((r, k) => {
    points.set([...r.p, 1], 4 * k);
    normals.set([...r.n, 0], 4 * k);
  });
  const textures = [patchTexture(), createDataTexture(gl, points, RECEIVERS.length, 1, 4), createDataTexture(gl, normals, RECEIVERS.length, 1, 4)];
  const common = { uPatches: 'sampler2D', uPoints: 'sampler2D', uNormals: 'sampler2D', uReceiver: 'int' } as const;
  const main = `out vec4 outColor;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec3 p = texelFetch(uPoints, texel, 0).xyz;
  vec3 n = texelFetch(uNormals, texel, 0).xyz;
  outColor = vec4(brightPatchIrradiance(uPatches, 1, uReceiver, p, n), 1.0);
}
`;
  const target = createFloatTarget(gl, RECEIVERS.length, 1, false);
  const inputs = { uPatches: textures[0], uPoints: textures[1], uNormals: textures[2], uReceiver: receiverSurface };
  if (occluder) {
    // A 0.3 m box at `occluder`; the other receivers' lines of sight pass beside it.
    const { bvh } = prepareObjects([placed('blocker', boxMesh(0.3, 0.3, 0.3), occluder)], { texelSize: 0.05, maxAtlasSize: 256 });
    const nodes = createDataTexture(gl, bvh.nodes, bvh.width, bvh.nodesHeight, 4);
    const triangles = createDataTexture(gl, bvh.triangles, bvh.width, bvh.trianglesHeight, 4);
    textures.push(nodes, triangles);
    const pass = fragmentPass({ ...common, uBvhNodes: 'sampler2D', uBvhTriangles: 'sampler2D' }, brightPatchGather({ bvhWidth: bvh.width }) + main);
    runPass(gl, passProgram(gl, pass), target, { ...inputs, uBvhNodes: nodes, uBvhTriangles: triangles });
  } else {
    runPass(gl, passProgram(gl, fragmentPass(common, brightPatchGather(null) + main)), target, inputs);
  }
  const rgba = readRgba(gl, target);
  deleteTarget(gl, target);
  for (const t of textures) gl.deleteTexture(t);
  return rgba;
}

function expectExitanceTimes(rgba: Float32Array, k: number, formFactor: number, tolerance: number): void {
  for (let c = 0; c < 3; c++) {
    const expected = EXITANCE[c] * formFactor;
    expect(Math.abs(rgba[4 * k + c] - expected), `${RECEIVERS[k].name}, channel ${c}`).toBeLessThanOrEqual(tolerance * expected);
  }
}

describe('the bright-patch loop (one chunk for the empty-room and the occluded pass)', () => {
  it('with occlusion (object receivers): M·F for receivers facing the patch, exactly 0 for those facing away, near and far', () => {
    // The blocker sits in the corner of the room, away from every line of sight.
    const e = irradiance([3, 0, 3]);
    RECEIVERS.forEach((r, k) => expectExitanceTimes(e, k, r.expected, r.tolerance));
  });

  it('a receiver turned away gets nothing where |cos θ_r| would give the full far-field value', () => {
    const e = irradiance([3, 0, 3]);
    const away = RECEIVERS.findIndex((r) => r.name === 'far, facing away');
    const toward = RECEIVERS.findIndex((r) => r.name === 'far, facing');
    expect(e[4 * toward]).toBeGreaterThan(0);
    expect(e[4 * away]).toBe(0);
  });

  it('an occluder on the line of sight hides the patch; a patch on the receiving surface is skipped', () => {
    // The box (0.3 m, y 0.8–1.1) lies between the patch and every receiver on the floor; the
    // receivers at y = 1.5 are above it and still see the patch.
    const e = irradiance([1.05, 0.8, 0.95]);
    RECEIVERS.forEach((r, k) => {
      if (r.p[1] > 1.1) expectExitanceTimes(e, k, r.expected, r.tolerance);
      else for (let c = 0; c < 3; c++) expect(e[4 * k + c], r.name).toBe(0);
    });
    const own = irradiance([3, 0, 3], CEILING);
    expect(own.every((x, i) => i % 4 === 3 || x === 0)).toBe(true);
  });

  it('without occlusion (room surfaces, every patch in front): the same M·F for receivers facing the patch', () => {
    const e = irradiance(null);
    RECEIVERS.forEach((r, k) => {
      if (r.expected > 0) expectExitanceTimes(e, k, r.expected, r.tolerance);
    });
  });
});
