/** Small meshes for the orientation tests (issue #35): an attic wedge, a quad, inside-out copies. */
import type { TriangleMesh } from '../../../src/core/mesh/triangleMesh';

const grey = [{ name: 'm', reflectance: [0.8, 0.8, 0.8] as [number, number, number] }];

/**
 * The attic wedge of issue #35 in a `w`-wide room: a closed prism under a roof slope, its
 * triangular section in the x–y plane (corners (0, 0), (w, 0), (0, h)) extruded along z over
 * [0, d]. 6 corners, 8 triangles, each counterclockwise seen from outside.
 */
export function wedgeMesh(w = 1.5, h = 1, d = 4): TriangleMesh {
  const positions = new Float32Array([0, 0, 0, w, 0, 0, 0, h, 0, 0, 0, d, w, 0, d, 0, h, d]);
  const indices = [
    0,
    2,
    1, // z = 0 end (normal −z)
    3,
    4,
    5, // z = d end (normal +z)
    0,
    1,
    4,
    0,
    4,
    3, // floor side (normal −y)
    0,
    3,
    5,
    0,
    5,
    2, // wall side (normal −x)
    1,
    2,
    5,
    1,
    5,
    4, // the slope (normal up and toward +x)
  ];
  return { positions, indices: Uint32Array.from(indices), materialOfTriangle: new Uint16Array(8), materials: grey };
}

/** A 1 × 1 m horizontal quad at `origin`, two triangles counterclockwise seen from above (normal +y), materials 0 and 1. */
export function quadMesh(origin: [number, number, number] = [0, 0, 0]): TriangleMesh {
  const [x, y, z] = origin;
  const positions = new Float32Array([x, y, z, x, y, z + 1, x + 1, y, z + 1, x + 1, y, z]);
  return {
    positions,
    indices: Uint32Array.from([0, 1, 2, 0, 2, 3]),
    materialOfTriangle: Uint16Array.from([0, 1]),
    materials: [...grey, { name: 'n', reflectance: [0.5, 0.5, 0.5] }],
  };
}

/** The same mesh with every triangle's winding reversed (corners 1 and 2 swapped), optionally moved. */
export function insideOut(mesh: TriangleMesh, move: [number, number, number] = [0, 0, 0]): TriangleMesh {
  const idx = Array.from(mesh.indices);
  for (let t = 0; t < idx.length; t += 3) [idx[t + 1], idx[t + 2]] = [idx[t + 2], idx[t + 1]];
  return { ...mesh, positions: mesh.positions.map((v, i) => v + move[i % 3]), indices: Uint32Array.from(idx) };
}

/** OBJ text of a mesh (1-based faces as the indices wind them), with an optional material library. */
export function objText(mesh: TriangleMesh, mtl?: { lib: string; material: string }): string {
  const lines: string[] = [];
  if (mtl) lines.push(`mtllib ${mtl.lib}`, `usemtl ${mtl.material}`);
  for (let v = 0; v < mesh.positions.length; v += 3) lines.push(`v ${mesh.positions[v]} ${mesh.positions[v + 1]} ${mesh.positions[v + 2]}`);
  for (let t = 0; t < mesh.indices.length; t += 3) lines.push(`f ${mesh.indices[t] + 1} ${mesh.indices[t + 1] + 1} ${mesh.indices[t + 2] + 1}`);
  return `${lines.join('\n')}\n`;
}

/** A Möbius strip of `n` segments around a unit circle (its cross-section turns by 180°): no consistent winding exists. */
export function mobiusMesh(n = 6): TriangleMesh {
  const positions: number[] = [];
  for (let i = 0; i < n; i++) {
    const phi = (2 * Math.PI * i) / n;
    const turn = phi / 2;
    for (const s of [-0.2, 0.2]) {
      const r = 1 + s * Math.cos(turn);
      positions.push(r * Math.cos(phi), s * Math.sin(turn), r * Math.sin(phi));
    }
  }
  const idx: number[] = [];
  for (let i = 0; i < n; i++) {
    const a = 2 * i,
      b = 2 * i + 1;
    // The last segment joins the first with its two edges swapped (the half turn).
    const [c, d] = i === n - 1 ? [1, 0] : [2 * i + 2, 2 * i + 3];
    idx.push(a, c, b, b, c, d);
  }
  return { positions: new Float32Array(positions), indices: Uint32Array.from(idx), materialOfTriangle: new Uint16Array(2 * n), materials: grey };
}

/**
 * A closed unit box [0, 1]³ whose top is a fan of four triangles round a centre vertex at height
 * `apexY`, every face counterclockwise from outside as long as the apex stays above the floor
 * (0 < apexY: a dent, or a tent above 1). With apexY < 0 the fan passes through the floor: the
 * part crosses itself and still encloses a positive signed volume (1 − (1 − apexY)/3 for the box
 * minus the pyramid), so the volume alone would call it outward.
 */
export function pushedThroughBox(apexY: number): TriangleMesh {
  // 0–3 floor corners, 4–7 top corners (x, z) = (0,0) (1,0) (1,1) (0,1); 8 the apex.
  const positions = new Float32Array([0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 0, 1, 0, 1, 1, 0, 1, 1, 1, 0, 1, 1, 0.5, apexY, 0.5]);
  const indices = [
    ...[0, 1, 2, 0, 2, 3], // floor (normal −y)
    ...[0, 4, 5, 0, 5, 1], // z = 0 (normal −z)
    ...[1, 5, 6, 1, 6, 2], // x = 1
    ...[2, 6, 7, 2, 7, 3], // z = 1
    ...[3, 7, 4, 3, 4, 0], // x = 0
    ...[4, 8, 5, 5, 8, 6, 6, 8, 7, 7, 8, 4], // the top fan (normal +y while the apex is above the floor)
  ];
  return { positions, indices: Uint32Array.from(indices), materialOfTriangle: new Uint16Array(indices.length / 3), materials: grey };
}

/**
 * Five triangles joined over manifold edges into one part, three of which share the spine P–Q
 * (P = origin, Q = (0, 0, 1); R, S, T round it): a non-manifold edge inside one part, so no winding
 * makes every edge run both ways once.
 */
export function spineFanMesh(): TriangleMesh {
  const ring = [0, 1, 2].map((k) => [Math.cos((2 * Math.PI * k) / 3), Math.sin((2 * Math.PI * k) / 3), 0.5]);
  const positions = new Float32Array([0, 0, 0, 0, 0, 1, ...ring.flat()]);
  const [P, Q, R, S, T] = [0, 1, 2, 3, 4];
  const indices = [P, Q, R, R, S, Q, P, Q, S, S, T, P, P, Q, T];
  return { positions, indices: Uint32Array.from(indices), materialOfTriangle: new Uint16Array(5), materials: grey };
}
