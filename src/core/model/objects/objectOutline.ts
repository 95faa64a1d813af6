/**
 * An object's silhouette seen from above, for the plan: the placed triangles' projections onto
 * the floor, rasterised on a grid of about 1 cm (coarser for meshes over 5 m, at most 512 cells
 * a side), the contour traced along the cell edges and simplified (collinear points dropped, then
 * Ramer–Douglas–Peucker within 0.6 cell). The grid is aligned to the mesh's own bounds, so a box
 * or a table top comes out as its exact rectangle. Computed in the mesh's frame once per mesh and
 * scale (cached), then turned by the yaw and moved to the position: a move or a turn costs only
 * the transform of a few vertices.
 */
import { positionBounds, type TriangleMesh } from '../../mesh/triangleMesh';
import { InputError } from '../../inputError';
import type { Configuration } from '../configuration/configuration';
import { objectPlacement, sourceMesh } from './objectGeometry';

/** A closed polygon in plan coordinates (x, z), metres; outer contours counterclockwise in (x, z), holes clockwise. */
export type PlanPolygon = readonly (readonly [number, number])[];

const TARGET_CELL = 0.01;
const MAX_CELLS = 512;

const cache = new WeakMap<TriangleMesh, Map<number, PlanPolygon[]>>();

/** The object's outline seen from above, in plan coordinates; polygons (holes included) whose union is the silhouette. */
export function objectOutline(config: Configuration, objectId: string): PlanPolygon[] {
  const object = config.objects.find((o) => o.id === objectId);
  if (!object) throw new InputError(`no object with id '${objectId}'`);
  const mesh = sourceMesh(config, object.source);
  if (!mesh) throw new InputError(`object ${objectId} has no mesh`);
  const local = localOutline(mesh, object.scale);
  const { position, yaw } = objectPlacement(object, config.room);
  // Ry: (x, z) → (c·x + s·z, −s·x + c·z), as src/core/mesh/placeMesh.ts; scale is already in the local outline.
  const t = (yaw * Math.PI) / 180;
  const [c, s] =
    yaw % 90 === 0
      ? [
          [1, 0],
          [0, 1],
          [-1, 0],
          [0, -1],
        ][(yaw / 90) % 4]
      : [Math.cos(t), Math.sin(t)];
  return local.map((poly) => poly.map(([x, z]) => [position[0] + c * x + s * z, position[2] - s * x + c * z] as const));
}

/** The outline of a mesh at a scale, in its own (scaled) frame; cached per mesh and scale. */
export function localOutline(mesh: TriangleMesh, scale: number): PlanPolygon[] {
  let perScale = cache.get(mesh);
  if (!perScale) cache.set(mesh, (perScale = new Map()));
  let out = perScale.get(scale);
  if (!out) perScale.set(scale, (out = traceOutline(mesh, scale)));
  return out;
}

function traceOutline(mesh: TriangleMesh, scale: number): PlanPolygon[] {
  const b = positionBounds(mesh.positions);
  const x0 = b.min[0] * scale;
  const z0 = b.min[2] * scale;
  const w = (b.max[0] - b.min[0]) * scale;
  const d = (b.max[2] - b.min[2]) * scale;
  if (!(w > 0 && d > 0)) return [];
  const cell = Math.max(TARGET_CELL, Math.max(w, d) / MAX_CELLS);
  const nx = Math.max(1, Math.ceil(w / cell - 1e-4));
  const nz = Math.max(1, Math.ceil(d / cell - 1e-4));
  const hx = w / nx;
  const hz = d / nz;
  const filled = new Uint8Array(nx * nz);
  const p = mesh.positions;
  const idx = mesh.indices;
  // A point of an edge-on face marks the cell it lies in; on a cell boundary (a closed mesh's side
  // face on a grid line, e.g. at its own bounds) it marks none: the faces beside it cover those cells.
  const mark = (x: number, z: number) => {
    const u = (x - x0) / hx;
    const v = (z - z0) / hz;
    if (Math.abs(u - Math.round(u)) < 1e-3 || Math.abs(v - Math.round(v)) < 1e-3) return; // Float32 vertices sit within 1e-3 cell of their line
    const i = Math.min(nx - 1, Math.max(0, Math.floor(u)));
    const j = Math.min(nz - 1, Math.max(0, Math.floor(v)));
    filled[j * nx + i] = 1;
  };
  for (let t = 0; t < idx.length; t += 3) {
    const ax = p[idx[t] * 3] * scale,
      az = p[idx[t] * 3 + 2] * scale;
    const bx = p[idx[t + 1] * 3] * scale,
      bz = p[idx[t + 1] * 3 + 2] * scale;
    const cx = p[idx[t + 2] * 3] * scale,
      cz = p[idx[t + 2] * 3 + 2] * scale;
    const area = (bx - ax) * (cz - az) - (cx - ax) * (bz - az);
    if (Math.abs(area) < 1e-4 * hx * hz) {
      // Seen edge-on (a vertical face): its projection is a segment; mark the cells it crosses.
      for (const [px, pz, qx, qz] of [
        [ax, az, bx, bz],
        [bx, bz, cx, cz],
        [cx, cz, ax, az],
      ]) {
        const n = Math.ceil(Math.hypot(qx - px, qz - pz) / (0.5 * Math.min(hx, hz))) + 1;
        for (let k = 0; k <= n; k++) mark(px + ((qx - px) * k) / n, pz + ((qz - pz) * k) / n);
      }
      continue;
    }
    // Cells whose centre lies inside the projected triangle (edges included, to a 1e-9 relative tolerance).
    const i0 = Math.max(0, Math.floor((Math.min(ax, bx, cx) - x0) / hx - 0.5));
    const i1 = Math.min(nx - 1, Math.ceil((Math.max(ax, bx, cx) - x0) / hx - 0.5));
    const j0 = Math.max(0, Math.floor((Math.min(az, bz, cz) - z0) / hz - 0.5));
    const j1 = Math.min(nz - 1, Math.ceil((Math.max(az, bz, cz) - z0) / hz - 0.5));
    const sign = Math.sign(area);
    const tol = -1e-9 * Math.abs(area);
    for (let j = j0; j <= j1; j++) {
      const z = z0 + (j + 0.5) * hz;
      for (let i = i0; i <= i1; i++) {
        const x = x0 + (i + 0.5) * hx;
        const e0 = sign * ((bx - ax) * (z - az) - (bz - az) * (x - ax));
        const e1 = sign * ((cx - bx) * (z - bz) - (cz - bz) * (x - bx));
        const e2 = sign * ((ax - cx) * (z - cz) - (az - cz) * (x - cx));
        if (e0 >= tol && e1 >= tol && e2 >= tol) filled[j * nx + i] = 1;
      }
    }
  }
  const loops = traceCells(filled, nx, nz);
  return loops.map((loop) =>
    simplify(
      loop.map(([i, j]) => [x0 + i * hx, z0 + j * hz] as [number, number]),
      0.6 * Math.min(hx, hz),
    ),
  );
}

/**
 * Closed loops along the boundary of the filled cells (grid vertex coordinates), each edge with
 * the filled cell on its left in (x, z); at a vertex where two filled cells touch diagonally the
 * left turn is taken, so such cells give separate loops.
 */
function traceCells(filled: Uint8Array, nx: number, nz: number): [number, number][][] {
  const at = (i: number, j: number) => i >= 0 && j >= 0 && i < nx && j < nz && filled[j * nx + i] === 1;
  const key = (i: number, j: number) => j * (nx + 1) + i;
  const out = new Map<number, [number, number][]>(); // start vertex → directions
  const add = (i: number, j: number, di: number, dj: number) => {
    const k = key(i, j);
    const list = out.get(k);
    if (list) list.push([di, dj]);
    else out.set(k, [[di, dj]]);
  };
  for (let j = 0; j < nz; j++) {
    for (let i = 0; i < nx; i++) {
      if (!at(i, j)) continue;
      if (!at(i, j - 1)) add(i, j, 1, 0);
      if (!at(i + 1, j)) add(i + 1, j, 0, 1);
      if (!at(i, j + 1)) add(i + 1, j + 1, -1, 0);
      if (!at(i - 1, j)) add(i, j + 1, 0, -1);
    }
  }
  const loops: [number, number][][] = [];
  for (const [start, dirs] of out) {
    while (dirs.length > 0) {
      let i = start % (nx + 1);
      let j = Math.floor(start / (nx + 1));
      let [di, dj] = dirs.pop()!;
      const loop: [number, number][] = [[i, j]];
      for (;;) {
        i += di;
        j += dj;
        const k = key(i, j);
        if (k === start) break; // every boundary is closed: the walk comes back
        const options = out.get(k)!;
        // Prefer the left (counterclockwise) turn, then straight on, then right.
        const prefs: [number, number][] = [
          [-dj, di],
          [di, dj],
          [dj, -di],
        ];
        const pickIndex = prefs.map(([a, b]) => options.findIndex(([u, v]) => u === a && v === b)).find((n) => n >= 0) ?? 0;
        [di, dj] = options.splice(pickIndex, 1)[0];
        loop.push([i, j]);
      }
      loops.push(loop);
    }
  }
  return loops;
}

/** Drops collinear points, then Ramer–Douglas–Peucker (tolerance `tol`) on the closed ring. */
function simplify(ring: [number, number][], tol: number): [number, number][] {
  const n = ring.length;
  const kept = ring.filter((q, k) => {
    const a = ring[(k + n - 1) % n];
    const b = ring[(k + 1) % n];
    return Math.abs((q[0] - a[0]) * (b[1] - a[1]) - (q[1] - a[1]) * (b[0] - a[0])) > 1e-12;
  });
  if (kept.length <= 4) return kept;
  // Split the ring at its first point and the point farthest from it, simplify both chains.
  let far = 1;
  let best = -1;
  for (let k = 1; k < kept.length; k++) {
    const dd = Math.hypot(kept[k][0] - kept[0][0], kept[k][1] - kept[0][1]);
    if (dd > best) [best, far] = [dd, k];
  }
  const first = rdp(kept.slice(0, far + 1), tol);
  const second = rdp([...kept.slice(far), kept[0]], tol);
  const result = [...first.slice(0, -1), ...second.slice(0, -1)];
  return result.length >= 3 ? result : kept;
}

function rdp(points: [number, number][], tol: number): [number, number][] {
  if (points.length <= 2) return points;
  const [a, b] = [points[0], points[points.length - 1]];
  const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
  let worst = 0;
  let at = 0;
  for (let k = 1; k < points.length - 1; k++) {
    const q = points[k];
    const dist = len > 0 ? Math.abs((b[0] - a[0]) * (a[1] - q[1]) - (a[0] - q[0]) * (b[1] - a[1])) / len : Math.hypot(q[0] - a[0], q[1] - a[1]);
    if (dist > worst) [worst, at] = [dist, k];
  }
  if (worst <= tol) return [a, b];
  return [...rdp(points.slice(0, at + 1), tol).slice(0, -1), ...rdp(points.slice(at), tol)];
}
