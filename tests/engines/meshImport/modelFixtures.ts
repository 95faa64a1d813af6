import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { TriangleMesh } from '../../../src/core/mesh/triangleMesh';
import type { MeshFile } from '../../../src/engines/meshImport/importedMesh';

export const MODELS = join(__dirname, '../../fixtures/models');

export function modelFile(name: string): MeshFile {
  return { name, bytes: new Uint8Array(readFileSync(join(MODELS, name))) };
}

export function textFile(name: string, text: string): MeshFile {
  return { name, bytes: new TextEncoder().encode(text) };
}

/**
 * The fixture table's analytic numbers (tests/fixtures/models/writeModelFixtures.ts): a 1.20 × 0.80 × 0.04 m
 * top at 0.71–0.75 m and four 0.05 × 0.05 × 0.71 m legs, each a closed box of 12 triangles.
 */
export const TABLE = {
  triangles: 60,
  volume: 1.2 * 0.8 * 0.04 + 4 * 0.05 * 0.05 * 0.71,
  area: 2 * (1.2 * 0.8 + 1.2 * 0.04 + 0.8 * 0.04) + 4 * 2 * (0.05 * 0.05 + 2 * 0.05 * 0.71),
  topArea: 2 * (1.2 * 0.8 + 1.2 * 0.04 + 0.8 * 0.04),
} as const;

/** Signed volume by the divergence theorem, Σ v0·(v1×v2)/6: positive when every triangle is counterclockwise seen from outside. */
export function signedVolume(mesh: TriangleMesh): number {
  let sum = 0;
  const p = mesh.positions;
  for (let t = 0; t < mesh.indices.length; t += 3) {
    const [a, b, c] = [mesh.indices[t] * 3, mesh.indices[t + 1] * 3, mesh.indices[t + 2] * 3];
    sum += p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) - p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) + p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return sum / 6;
}

/** Surface area per material index. */
export function areaByMaterial(mesh: TriangleMesh): number[] {
  const out = mesh.materials.map(() => 0);
  const p = mesh.positions;
  for (let t = 0; t < mesh.indices.length / 3; t++) {
    const [a, b, c] = [mesh.indices[3 * t] * 3, mesh.indices[3 * t + 1] * 3, mesh.indices[3 * t + 2] * 3];
    const u = [p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]];
    const v = [p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2]];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    out[mesh.materialOfTriangle[t]] += Math.hypot(n[0], n[1], n[2]) / 2;
  }
  return out;
}

/** Every edge of every triangle is shared with exactly one other triangle going the other way (a closed, consistently wound surface). */
export function isClosedAndConsistent(mesh: TriangleMesh): boolean {
  const edges = new Map<string, number>();
  for (let t = 0; t < mesh.indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const key = `${mesh.indices[t + e]}>${mesh.indices[t + ((e + 1) % 3)]}`;
      edges.set(key, (edges.get(key) ?? 0) + 1);
    }
  }
  for (const [key, n] of edges) {
    const [a, b] = key.split('>');
    if (n !== 1 || edges.get(`${b}>${a}`) !== 1) return false;
  }
  return true;
}
