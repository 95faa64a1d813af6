/**
 * Orientation of imported meshes (issue #35, docs/furniture.md "Which side of a face is lit"):
 * closed parts outward whatever the file's winding, open two-sided parts with a reversed back copy
 * BACK_SIDE_OFFSET behind, undecidable parts two-sided, the furniture library already outward.
 */
import { describe, expect, it } from 'vitest';
import { BACK_SIDE_OFFSET, orientMesh } from '../../../src/core/mesh/orientMesh';
import { connectedParts } from '../../../src/core/mesh/connectedParts';
import { coincidentPairs } from '../../../src/core/mesh/coincidentPairs';
import { meshEdges } from '../../../src/core/mesh/meshEdges';
import { composeParts } from '../../../src/core/model/objects/furniture/meshParts';
import type { TriangleMesh } from '../../../src/core/mesh/triangleMesh';
import { FURNITURE_LIBRARY, furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { createRng } from '../../fuzz/mutate';
import { boxMesh } from '../../engines/bake/objects/objectFixtures';
import { isClosedAndConsistent, signedVolume } from '../../engines/meshImport/modelFixtures';
import { partSelfIntersects } from '../../../src/core/mesh/partSelfIntersects';
import { wedgeMesh, insideOut, mobiusMesh, pushedThroughBox, quadMesh, spineFanMesh } from './orientFixtures';

const never = () => false;
const always = () => true;

/** Unit normal of triangle t. */
function normalOf(mesh: TriangleMesh, t: number): number[] {
  const p = mesh.positions;
  const [a, b, c] = [0, 1, 2].map((k) => 3 * mesh.indices[3 * t + k]);
  const e1 = [0, 1, 2].map((i) => p[b + i] - p[a + i]);
  const e2 = [0, 1, 2].map((i) => p[c + i] - p[a + i]);
  const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
  const len = Math.hypot(n[0], n[1], n[2]);
  return n.map((x) => x / len);
}

function withIndices(mesh: TriangleMesh, indices: number[]): TriangleMesh {
  return { ...mesh, indices: Uint32Array.from(indices) };
}

describe('closed parts', () => {
  it('an outward box and wedge are left exactly as they are', () => {
    for (const mesh of [boxMesh(1, 0.5, 2), wedgeMesh()]) {
      const { mesh: out, summary } = orientMesh(mesh, always);
      expect(Array.from(out.indices)).toEqual(Array.from(mesh.indices));
      expect(out.positions).toEqual(mesh.positions);
      expect(summary).toMatchObject({ parts: 1, closed: 1, turnedOutward: 0, trianglesReversed: 0, twoSided: 0, undecided: 0, backTriangles: 0 });
    }
  });

  it('inside-out (every triangle reversed) is turned back to the outward winding, triangle by triangle', () => {
    for (const mesh of [boxMesh(1, 0.5, 2), wedgeMesh()]) {
      const inverted = insideOut(mesh);
      expect(signedVolume(inverted)).toBeLessThan(0);
      const { mesh: out, summary } = orientMesh(inverted, always);
      expect(Array.from(out.indices)).toEqual(Array.from(mesh.indices));
      expect(summary).toMatchObject({ closed: 1, turnedOutward: 1, trianglesReversed: mesh.indices.length / 3, twoSided: 0, backTriangles: 0 });
    }
  });

  it('a box with every other triangle reversed (inconsistent winding) comes out outward and consistent', () => {
    const box = boxMesh(2, 1, 1);
    const idx = Array.from(box.indices);
    for (let t = 0; t < 12; t += 2) [idx[3 * t + 1], idx[3 * t + 2]] = [idx[3 * t + 2], idx[3 * t + 1]];
    const { mesh: out, summary } = orientMesh(withIndices(box, idx), always);
    expect(Array.from(out.indices)).toEqual(Array.from(box.indices));
    expect(summary.trianglesReversed).toBe(6);
    expect(isClosedAndConsistent(out)).toBe(true);
  });

  it('random flips of random triangles of every library item, moved far from the origin: the same triangles as orienting the item as built', () => {
    const rng = createRng(35);
    for (const item of FURNITURE_LIBRARY) {
      const mesh = furnitureMesh(item.id);
      const move = (m: TriangleMesh): TriangleMesh => ({ ...m, positions: m.positions.map((x, i) => x + [123.25, -4.5, 61.75][i % 3]) });
      const idx = Array.from(mesh.indices);
      for (let t = 0; t < idx.length / 3; t++) if (rng.next() < 0.5) [idx[3 * t + 1], idx[3 * t + 2]] = [idx[3 * t + 2], idx[3 * t + 1]];
      const scrambled = orientMesh(move(withIndices(mesh, idx)), always);
      const built = orientMesh(move(mesh), always);
      expect(scrambled.summary.backTriangles + scrambled.summary.undecided, item.id).toBe(0);
      expect(Array.from(scrambled.mesh.indices), item.id).toEqual(Array.from(built.mesh.indices));
    }
  });

  it('a sheet a file made two-sided by repeating each triangle the other way round keeps one copy and gets its own back side', () => {
    const sheet = quadMesh();
    const doubled = withIndices(sheet, [0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2]);
    const { mesh: out, summary } = orientMesh(doubled, never);
    expect(summary).toMatchObject({ parts: 1, closed: 0, twoSided: 1, droppedCopies: 2, backTriangles: 2 });
    expect(out.indices.length).toBe(12);
    expect(normalOf(out, 0)[1]).toBeCloseTo(1, 12);
    expect(normalOf(out, 2)[1]).toBeCloseTo(-1, 12);
  });

  it('two boxes glued face to face (shared corners, as cushions modelled side by side): one closed solid, the glued faces inside it; inside-out gives the same triangles', () => {
    const glued = gluedBoxes();
    const written = orientMesh(glued, always);
    expect(written.summary).toMatchObject({ parts: 1, closed: 1, turnedOutward: 0, enclosedFaces: 4, backTriangles: 0, undecided: 0 });
    const inverted = orientMesh(insideOut(glued), always);
    expect(inverted.summary).toMatchObject({ parts: 1, closed: 1, turnedOutward: 1, enclosedFaces: 4 });
    expect(Array.from(inverted.mesh.indices)).toEqual(Array.from(written.mesh.indices));
  });
});

/** Two 1 m cubes side by side along x, sharing the face x = 1 corner for corner (24 triangles, 4 of them on the shared face). */
function gluedBoxes(): TriangleMesh {
  const a = boxMesh(1, 1, 1);
  const positions = [...a.positions, ...a.positions.map((v, i) => (i % 3 === 0 ? v + 1 : v))];
  const indices = [...a.indices, ...Array.from(a.indices, (i) => i + 8)];
  return { positions: new Float32Array(positions), indices: Uint32Array.from(indices), materialOfTriangle: new Uint16Array(24), materials: a.materials };
}

describe('the furniture library', () => {
  it('every part of every item is closed and wound outward (positive volume), and orienting an item changes no triangle outside its glued faces', () => {
    for (const item of FURNITURE_LIBRARY) {
      for (const part of item.parts()) {
        const alone = composeParts([part], () => [0.5, 0.5, 0.5]);
        expect(isClosedAndConsistent(alone), item.id).toBe(true);
        expect(signedVolume(alone), item.id).toBeGreaterThan(0);
      }
      const mesh = furnitureMesh(item.id);
      const { mesh: out, summary } = orientMesh(mesh, always);
      expect(summary.closed, item.id).toBe(summary.parts);
      expect(summary.turnedOutward + summary.trianglesReversed + summary.backTriangles + summary.undecided + summary.droppedCopies, item.id).toBe(0);
      // Glued faces (a cushion against its neighbour) are wound canonically; every other triangle is as built.
      const glued = new Set(coincidentPairs(mesh, meshEdges(mesh).vertexId).flat());
      for (let t = 0; t < mesh.indices.length / 3; t++) {
        if (glued.has(t)) continue;
        expect(Array.from(out.indices.subarray(3 * t, 3 * t + 3)), `${item.id} triangle ${t}`).toEqual(Array.from(mesh.indices.subarray(3 * t, 3 * t + 3)));
      }
    }
  });
});

describe('open parts', () => {
  it('a two-sided quad: the back is a reversed copy on the file’s corners, the front moves 0.5 mm forward, materials kept', () => {
    const quad = quadMesh();
    const { mesh: out, summary } = orientMesh(quad, always);
    expect(summary).toMatchObject({ parts: 1, closed: 0, twoSided: 1, oneSided: 0, backTriangles: 2, trianglesReversed: 0 });
    expect(out.indices.length).toBe(12);
    expect(out.positions.length).toBe(24);
    for (let t = 0; t < 2; t++) {
      const front = normalOf(out, t);
      const backNormal = normalOf(out, t + 2);
      expect(front[1]).toBeCloseTo(1, 12);
      expect(backNormal[1]).toBeCloseTo(-1, 12);
    }
    // The back on the original vertices (the lowest point of the model stays where the file has it).
    expect(Array.from(out.indices.subarray(6))).toEqual([0, 2, 1, 0, 3, 2]);
    expect(out.positions.subarray(0, 12)).toEqual(quad.positions);
    for (let v = 4; v < 8; v++) {
      expect(out.positions[3 * v + 1]).toBeCloseTo(quad.positions[3 * (v - 4) + 1] + BACK_SIDE_OFFSET, 7);
      expect(out.positions[3 * v]).toBe(quad.positions[3 * (v - 4)]);
    }
    expect(Array.from(out.materialOfTriangle)).toEqual([0, 1, 0, 1]);
  });

  it('a one-sided open part is left exactly as the file winds it, each triangle its own way', () => {
    const quad = withIndices(
      quadMesh(),
      [0, 1, 2, 0, 2, 3].map((v, i) => (i === 4 ? 3 : i === 5 ? 2 : v)),
    );
    const { mesh: out, summary } = orientMesh(quad, never);
    expect(Array.from(out.indices)).toEqual(Array.from(quad.indices));
    expect(summary).toMatchObject({ oneSided: 1, twoSided: 0, backTriangles: 0 });
  });

  it('a two-sided strip with inconsistent windings is made consistent (majority kept) before its back is added', () => {
    // Three quads in a row, the middle triangle pair reversed in the file.
    const positions = new Float32Array([0, 1, 0, 1, 1, 0, 2, 1, 0, 3, 1, 0, 0, 1, 1, 1, 1, 1, 2, 1, 1, 3, 1, 1]);
    const up = (a: number, b: number, c: number) => [a, c, b];
    const idx = [...up(0, 1, 5), ...up(0, 5, 4), 1, 2, 6, 1, 6, 5, ...up(2, 3, 7), ...up(2, 7, 6)];
    const mesh: TriangleMesh = { positions, indices: Uint32Array.from(idx), materialOfTriangle: new Uint16Array(6), materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] }] };
    const { mesh: out, summary } = orientMesh(mesh, always);
    expect(summary.trianglesReversed).toBe(2);
    for (let t = 0; t < 6; t++) expect(normalOf(out, t)[1]).toBeCloseTo(1, 12);
    for (let t = 6; t < 12; t++) expect(normalOf(out, t)[1]).toBeCloseTo(-1, 12);
    // The back copy shares its corners like the front (8 new vertices, not 18).
    expect(out.positions.length / 3).toBe(16);
  });
});

describe('parts that cannot be oriented', () => {
  it('three sheets meeting on one edge (a fin) are three open parts, each as the file winds it when one-sided', () => {
    const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0.2, 0.5, 0, 1]);
    const mesh: TriangleMesh = { positions, indices: Uint32Array.from([0, 1, 2, 0, 1, 3, 1, 0, 4]), materialOfTriangle: new Uint16Array(3), materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] }] };
    expect(connectedParts(mesh)).toHaveLength(3);
    const { mesh: out, summary } = orientMesh(mesh, never);
    expect(summary).toMatchObject({ parts: 3, oneSided: 3, backTriangles: 0 });
    expect(Array.from(out.indices)).toEqual(Array.from(mesh.indices));
  });

  it('a fin on the middle edge of a strip (three triangles on one edge) is a part of its own; made two-sided, each copy along its own normal', () => {
    // A strip of two quads (manifold edges join them) plus a fin on the middle edge that also touches both quads' far corners.
    const positions = new Float32Array([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 1, 1, 0, 1, 2, 0, 1, 1, 1, 0.5]);
    const idx = [0, 3, 4, 0, 4, 1, 1, 4, 5, 1, 5, 2, 1, 4, 6];
    const mesh: TriangleMesh = { positions, indices: Uint32Array.from(idx), materialOfTriangle: new Uint16Array(5), materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] }] };
    const parts = connectedParts(mesh);
    expect(parts.some((p) => p.flip === null) || parts.length > 1).toBe(true);
    const { mesh: out, summary } = orientMesh(mesh, always);
    expect(summary.backTriangles).toBe(5);
    for (let t = 0; t < out.indices.length / 3; t++) expect(normalOf(out, t).every(Number.isFinite)).toBe(true);
  });

  it('three triangles of one part on one edge (non-manifold inside a part): no winding, two-sided whatever the file says', () => {
    const mesh = spineFanMesh();
    const parts = connectedParts(mesh);
    expect(parts).toHaveLength(1);
    expect(parts[0].flip).toBeNull();
    // One-sided by the file (a glTF material without doubleSided): still two-sided, counted as undecided.
    expect(orientMesh(mesh, never).summary).toMatchObject({ parts: 1, undecided: 1, oneSided: 0, backTriangles: 5 });
  });

  it('a closed box whose top is pushed through its floor crosses itself: two-sided and undecided, although its signed volume is positive', () => {
    const through = pushedThroughBox(-0.5);
    // What the volume alone would say: closed, consistent, positive (1 − 1.5/3 = 0.5 m³).
    expect(isClosedAndConsistent(through)).toBe(true);
    expect(signedVolume(through)).toBeCloseTo(0.5, 6);
    expect(orientMesh(through, never).summary).toMatchObject({ parts: 1, closed: 0, undecided: 1, backTriangles: 14 });
    expect(orientMesh(insideOut(through), never).summary).toMatchObject({ parts: 1, closed: 0, undecided: 1, backTriangles: 14 });
  });

  it('the same box with its top dented, raised into a tent or touching the floor at one point does not cross itself: closed and outward', () => {
    for (const apexY of [1.5, 1, 0.5, 0.01, 0]) {
      const box = pushedThroughBox(apexY);
      expect(partSelfIntersects(box.positions, box.indices, meshEdges(box).vertexId, connectedParts(box)[0]), `apex ${apexY}`).toBe(false);
      expect(orientMesh(insideOut(box), never).summary, `apex ${apexY}`).toMatchObject({ closed: 1, turnedOutward: 1, undecided: 0, backTriangles: 0 });
    }
    // Just below the floor the fan crosses it.
    const through = pushedThroughBox(-1e-3);
    expect(partSelfIntersects(through.positions, through.indices, meshEdges(through).vertexId, connectedParts(through)[0])).toBe(true);
  });

  it('a Möbius strip has no consistent winding: two-sided', () => {
    const n = 6;
    const mesh = mobiusMesh(n);
    const parts = connectedParts(mesh);
    expect(parts).toHaveLength(1);
    expect(parts[0].flip).toBeNull();
    expect(orientMesh(mesh, never).summary).toMatchObject({ undecided: 1, backTriangles: 2 * n });
  });
});

describe('several parts', () => {
  it('each part is oriented on its own: an outward box, an inside-out wedge and a loose quad', () => {
    const box = boxMesh(0.5, 0.5, 0.5);
    const wedge = insideOut(wedgeMesh(), [3, 0, 0]);
    const quad = quadMesh([0, 2, 0]);
    const parts = [box, wedge, quad];
    let offset = 0;
    const positions: number[] = [];
    const indices: number[] = [];
    for (const m of parts) {
      positions.push(...m.positions);
      indices.push(...Array.from(m.indices, (i) => i + offset));
      offset += m.positions.length / 3;
    }
    const mesh: TriangleMesh = { positions: new Float32Array(positions), indices: Uint32Array.from(indices), materialOfTriangle: new Uint16Array(indices.length / 3), materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] }] };
    const { summary } = orientMesh(mesh, always);
    expect(summary).toEqual({ parts: 3, closed: 2, turnedOutward: 1, trianglesReversed: 8, twoSided: 1, oneSided: 0, undecided: 0, enclosedFaces: 0, droppedCopies: 0, backTriangles: 2 });
  });
});
