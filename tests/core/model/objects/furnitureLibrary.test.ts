import { describe, expect, it } from 'vitest';
import { positionBounds } from '../../../../src/core/mesh/triangleMesh';
import { FURNITURE_LIBRARY, furnitureMesh } from '../../../../src/core/model/objects/furniture/furnitureLibrary';
import { OBJECT_FINISHES, objectFinishRgb } from '../../../../src/core/model/objects/furniture/objectFinishes';
import type { MeshPart } from '../../../../src/core/model/objects/furniture/meshParts';
import { PERSON_HEAD, PERSON_STATURE, standingPersonParts } from '../../../../src/core/model/objects/furniture/standingPerson';
import { reflectanceProblem } from '../../../../src/core/model/lightingScene/reflectance';

/** Signed volume by the divergence theorem: Σ v0 · (v1 × v2) / 6 over the triangles (positive for outward CCW winding). */
function signedVolume(part: MeshPart): number {
  const p = part.positions;
  let v = 0;
  for (let t = 0; t < part.indices.length; t += 3) {
    const [a, b, c] = [part.indices[t] * 3, part.indices[t + 1] * 3, part.indices[t + 2] * 3];
    v += p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) - p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) + p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return v / 6;
}

/** Each directed edge once, and its reverse once: a closed, consistently wound surface. */
function edgeProblem(part: MeshPart): string | null {
  const directed = new Map<string, number>();
  for (let t = 0; t < part.indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const key = `${part.indices[t + e]}>${part.indices[t + ((e + 1) % 3)]}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  }
  for (const [key, n] of directed) {
    const [a, b] = key.split('>');
    if (n !== 1) return `edge ${key} used ${n} times in one direction`;
    if (directed.get(`${b}>${a}`) !== 1) return `edge ${key} has no opposite`;
  }
  return null;
}

/** Volume of a box or frustum part from its bounds is not exact for frusta, so boxes only: w·h·d. */
function boxVolume(part: MeshPart): number {
  const b = positionBounds(part.positions);
  return (b.max[0] - b.min[0]) * (b.max[1] - b.min[1]) * (b.max[2] - b.min[2]);
}

describe('furniture library', () => {
  it('has at least 12 items with unique ids, including the ones the brief names', () => {
    expect(FURNITURE_LIBRARY.length).toBeGreaterThanOrEqual(12);
    expect(new Set(FURNITURE_LIBRARY.map((i) => i.id)).size).toBe(FURNITURE_LIBRARY.length);
    for (const id of ['dining-table', 'coffee-table', 'chair', 'sofa', 'armchair', 'sideboard', 'open-shelf', 'bed', 'desk', 'kitchen-island', 'picture', 'floor-plant', 'person']) {
      expect(FURNITURE_LIBRARY.some((i) => i.id === id)).toBe(true);
    }
  });

  for (const item of FURNITURE_LIBRARY) {
    it(`${item.id}: closed outward parts, stated bounds, origin, ≤ 2000 triangles, finishes`, () => {
      const parts = item.parts();
      for (const part of parts) {
        expect(edgeProblem(part)).toBeNull();
        const v = signedVolume(part);
        expect(v).toBeGreaterThan(0);
        // 8-vertex parts are boxes: the signed volume equals w·h·d (relative 1e-9)
        if (part.positions.length === 24) expect(Math.abs(v - boxVolume(part)) / boxVolume(part)).toBeLessThan(1e-9);
      }
      const mesh = furnitureMesh(item.id);
      expect(mesh.indices.length / 3).toBeLessThanOrEqual(2000);
      const b = positionBounds(mesh.positions);
      const tol = 1e-6; // Float32 positions
      expect(b.max[0] - b.min[0]).toBeCloseTo(item.width, 6);
      expect(b.max[1] - b.min[1]).toBeCloseTo(item.height, 6);
      expect(b.max[2] - b.min[2]).toBeCloseTo(item.depth, 6);
      // origin: centred in x; floor items: on the floor and centred in z; wall items: back on z = 0, centred in y
      expect(Math.abs(b.min[0] + b.max[0])).toBeLessThan(tol);
      if (item.mount === 'floor') {
        expect(Math.abs(b.min[1])).toBeLessThan(tol);
        expect(Math.abs(b.min[2] + b.max[2])).toBeLessThan(tol);
      } else {
        expect(Math.abs(b.min[2])).toBeLessThan(tol);
        expect(Math.abs(b.min[1] + b.max[1])).toBeLessThan(tol);
      }
      // every material has a default finish, and its reflectance is that finish's
      expect(mesh.materials.map((m) => m.name).sort()).toEqual(Object.keys(item.finishes).sort());
      for (const m of mesh.materials) expect(m.reflectance).toEqual(objectFinishRgb(item.finishes[m.name]));
      // every triangle's material index is in range, and every material is used
      expect(new Set(mesh.materialOfTriangle).size).toBe(mesh.materials.length);
    });
  }

  it('the dining table is 180 × 90 × 75 cm with the floor under its top open (four legs only)', () => {
    const mesh = furnitureMesh('dining-table');
    const b = positionBounds(mesh.positions);
    expect([b.max[0] - b.min[0], b.max[2] - b.min[2], b.max[1]].map((x) => Math.round(x * 1000))).toEqual([1800, 900, 750]);
    // floor contact area: the legs' footprint (4 × 6 × 6 cm) is under 1 % of the top
    const parts = FURNITURE_LIBRARY.find((i) => i.id === 'dining-table')!.parts();
    const onFloor = parts.filter((p) => positionBounds(p.positions).min[1] === 0);
    expect(onFloor.length).toBe(4);
    const area = onFloor.reduce((s, p) => {
      const pb = positionBounds(p.positions);
      return s + (pb.max[0] - pb.min[0]) * (pb.max[2] - pb.min[2]);
    }, 0);
    expect(area).toBeCloseTo(4 * 0.06 * 0.06, 9);
  });

  it('the standing person is 1.75 m', () => {
    expect(positionBounds(furnitureMesh('person').positions).max[1]).toBeCloseTo(1.75, 6);
  });

  it('the standing person has human proportions (Tilley; the head 1/7.5 of the stature)', () => {
    const parts = standingPersonParts();
    const bounds = parts.map((p) => ({ material: p.material, ...positionBounds(p.positions) }));
    // the head: the skin part that reaches highest; chin to crown H/7.5 within 1 cm, narrower than long
    const head = bounds.filter((b) => b.material === 'skin').reduce((a, b) => (b.max[1] > a.max[1] ? b : a));
    expect(Math.abs(head.max[1] - head.min[1] - PERSON_STATURE / 7.5)).toBeLessThan(0.01);
    expect(head.max[1]).toBeCloseTo(PERSON_HEAD.crown, 6);
    const headWidth = head.max[0] - head.min[0];
    expect(headWidth).toBeGreaterThan(0.14);
    expect(headWidth).toBeLessThan(head.max[2] - head.min[2]);
    // the hair crowns the head at the stature
    const hair = bounds.find((b) => b.material === 'hair')!;
    expect(hair.max[1]).toBeCloseTo(PERSON_STATURE, 6);
    // widest at the shoulders (1.3-1.45 m, NASA-STD-3000: acromion 0.82 H), a neck narrower than the head
    const widest = bounds.reduce((a, b) => (b.max[0] > a.max[0] ? b : a));
    expect(widest.max[0]).toBeCloseTo(0.25, 6);
    expect(widest.max[1]).toBeGreaterThan(1.3);
    expect(widest.max[1]).toBeLessThan(1.45);
    // two legs, two arms and two hands: mirrored pairs of trouser and skin parts
    const left = bounds.filter((b) => b.max[0] < 0).length;
    const right = bounds.filter((b) => b.min[0] > 0).length;
    expect(left).toBe(right);
    expect(left).toBeGreaterThanOrEqual(4);
    // fingertips at 0.39 H, crotch about 0.47 H (Tilley): the hands end between 0.6 and 0.75 m
    const hands = bounds.filter((b) => b.material === 'skin' && b.min[1] < 0.8);
    expect(hands.length).toBe(2);
    for (const h of hands) expect(h.min[1] / PERSON_STATURE).toBeCloseTo(0.39, 1);
  });

  it('object finishes are valid reflectances with sRGB display colours that encode them', () => {
    expect(new Set(OBJECT_FINISHES.map((f) => f.id)).size).toBe(OBJECT_FINISHES.length);
    const encode = (c: number) => Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055));
    for (const f of OBJECT_FINISHES) {
      expect(reflectanceProblem(f.reflectance)).toBeNull();
      const rgb = objectFinishRgb(f.id);
      expect(f.display).toBe(`#${rgb.map((c) => encode(c).toString(16).padStart(2, '0')).join('')}`);
    }
  });
});
