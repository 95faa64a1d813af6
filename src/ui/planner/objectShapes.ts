/**
 * Objects' outlines seen from above, for the plan: the union of the mesh's triangles projected
 * onto the floor, traced as polygons (outer loops and holes, even-odd). Computed once per mesh
 * in its own frame on a fine grid, then placed like the mesh (world = T·Ry(yaw)·S·local,
 * src/core/mesh/placeMesh.ts), so moving, turning or resizing an object costs a few hundred
 * point transforms, not a new trace.
 */
import type { Configuration } from '../../core/model/configuration/configuration';
import { objectPlacement, sourceMesh } from '../../core/model/objects/objectGeometry';
import { placementTransform } from '../../core/mesh/placeMesh';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import type { PlanPoint } from './viewTransform';

/** Grid cell of the trace, metres in the mesh's frame: half a centimetre, finer than any part the plan shows. */
export const OUTLINE_CELL = 0.005;
/** Cells along the longer side at most: a 10 m imported kitchen is traced at 1.7 cm, not 0.5 cm. */
export const OUTLINE_MAX_CELLS = 600;

type Loop = PlanPoint[];

const localOutlines = new WeakMap<TriangleMesh, Loop[]>();

/**
 * The mesh's silhouette from above in its own frame (x, z): cells whose centre lies in a
 * projected triangle, or that hold a triangle's centroid (so parts thinner than a cell still show), traced
 * along the cell edges between filled and empty cells, then simplified.
 */
export function meshOutline(mesh: TriangleMesh): Loop[] {
  const hit = localOutlines.get(mesh);
  if (hit) return hit;
  const p = mesh.positions;
  let minX = Infinity,
    maxX = -Infinity,
    minZ = Infinity,
    maxZ = -Infinity;
  for (let i = 0; i < p.length; i += 3) {
    minX = Math.min(minX, p[i]);
    maxX = Math.max(maxX, p[i]);
    minZ = Math.min(minZ, p[i + 2]);
    maxZ = Math.max(maxZ, p[i + 2]);
  }
  if (!(maxX >= minX && maxZ >= minZ)) {
    localOutlines.set(mesh, []);
    return [];
  }
  const cell = Math.max(OUTLINE_CELL, Math.max(maxX - minX, maxZ - minZ) / OUTLINE_MAX_CELLS);
  const nx = Math.max(1, Math.ceil((maxX - minX) / cell - 1e-6));
  const nz = Math.max(1, Math.ceil((maxZ - minZ) / cell - 1e-6));
  const filled = new Uint8Array(nx * nz);
  const clampX = (i: number) => Math.min(nx - 1, Math.max(0, i));
  const clampZ = (k: number) => Math.min(nz - 1, Math.max(0, k));
  const idx = mesh.indices;
  for (let t = 0; t < idx.length; t += 3) {
    const ax = p[idx[t] * 3],
      az = p[idx[t] * 3 + 2];
    const bx = p[idx[t + 1] * 3],
      bz = p[idx[t + 1] * 3 + 2];
    const cx = p[idx[t + 2] * 3],
      cz = p[idx[t + 2] * 3 + 2];
    const area = (bx - ax) * (cz - az) - (bz - az) * (cx - ax);
    if (Math.abs(area) < 1e-12) continue; // seen edge-on from above (a side face): its neighbours cover it
    const i0 = clampX(Math.floor((Math.min(ax, bx, cx) - minX) / cell));
    const i1 = clampX(Math.floor((Math.max(ax, bx, cx) - minX) / cell));
    const k0 = clampZ(Math.floor((Math.min(az, bz, cz) - minZ) / cell));
    const k1 = clampZ(Math.floor((Math.max(az, bz, cz) - minZ) / cell));
    // The centroid lies strictly inside the triangle: its cell is filled even when the part is thinner than a cell.
    filled[clampZ(Math.floor(((az + bz + cz) / 3 - minZ) / cell)) * nx + clampX(Math.floor(((ax + bx + cx) / 3 - minX) / cell))] = 1;
    const s = Math.sign(area);
    for (let k = k0; k <= k1; k++) {
      const z = minZ + (k + 0.5) * cell;
      for (let i = i0; i <= i1; i++) {
        const x = minX + (i + 0.5) * cell;
        // Inside when the centre is on the same side of all three edges (edge functions, either winding).
        const e0 = s * ((bx - ax) * (z - az) - (bz - az) * (x - ax));
        const e1 = s * ((cx - bx) * (z - bz) - (cz - bz) * (x - bx));
        const e2 = s * ((ax - cx) * (z - cz) - (az - cz) * (x - cx));
        if (e0 >= 0 && e1 >= 0 && e2 >= 0) filled[k * nx + i] = 1;
      }
    }
  }
  const loops = traceCells(filled, nx, nz).map((loop) =>
    simplifyLoop(
      loop.map(([i, k]) => ({ x: minX + i * cell, z: minZ + k * cell })),
      cell * 0.75,
    ),
  );
  localOutlines.set(mesh, loops);
  return loops;
}

/**
 * Closed loops along the cell edges between filled and empty cells (grid corners (i, k)):
 * each boundary edge is directed with the filled cell on its left, then edges are chained.
 */
function traceCells(filled: Uint8Array, nx: number, nz: number): [number, number][][] {
  const at = (i: number, k: number) => i >= 0 && k >= 0 && i < nx && k < nz && filled[k * nx + i] === 1;
  const key = (i: number, k: number) => k * (nx + 1) + i;
  const next = new Map<number, [number, number][]>();
  const add = (a: [number, number], b: [number, number]) => {
    const list = next.get(key(a[0], a[1]));
    if (list) list.push(b);
    else next.set(key(a[0], a[1]), [b]);
  };
  for (let k = 0; k < nz; k++) {
    for (let i = 0; i < nx; i++) {
      if (!at(i, k)) continue;
      if (!at(i, k - 1)) add([i + 1, k], [i, k]);
      if (!at(i, k + 1)) add([i, k + 1], [i + 1, k + 1]);
      if (!at(i - 1, k)) add([i, k], [i, k + 1]);
      if (!at(i + 1, k)) add([i + 1, k + 1], [i + 1, k]);
    }
  }
  const loops: [number, number][][] = [];
  for (const [startKey, list] of next) {
    while (list.length > 0) {
      const start: [number, number] = [startKey % (nx + 1), Math.floor(startKey / (nx + 1))];
      const loop: [number, number][] = [start];
      let cur = list.pop()!;
      while (key(cur[0], cur[1]) !== startKey) {
        loop.push(cur);
        const out = next.get(key(cur[0], cur[1]));
        if (!out || out.length === 0) break;
        cur = out.pop()!;
      }
      loops.push(loop);
    }
  }
  return loops;
}

/** Drops collinear corners, then Douglas–Peucker within `tolerance` (a cell's staircase on a round part becomes a smooth edge). */
function simplifyLoop(loop: Loop, tolerance: number): Loop {
  if (loop.length <= 4) return loop;
  // Split the closed loop at its first point and the point farthest from it.
  let far = 0;
  let best = -1;
  loop.forEach((q, i) => {
    const d = Math.hypot(q.x - loop[0].x, q.z - loop[0].z);
    if (d > best) [best, far] = [d, i];
  });
  const a = douglasPeucker(loop.slice(0, far + 1), tolerance);
  const b = douglasPeucker([...loop.slice(far), loop[0]], tolerance);
  return withoutCollinear([...a.slice(0, -1), ...b.slice(0, -1)]);
}

/** The loop without corners that lie on the line through their neighbours (the split point among them). */
function withoutCollinear(loop: Loop): Loop {
  const keep = loop.filter((q, i) => {
    const a = loop[(i + loop.length - 1) % loop.length];
    const b = loop[(i + 1) % loop.length];
    return Math.abs((b.x - a.x) * (q.z - a.z) - (b.z - a.z) * (q.x - a.x)) > 1e-12;
  });
  return keep.length >= 3 ? keep : loop;
}

function douglasPeucker(points: Loop, tolerance: number): Loop {
  if (points.length <= 2) return points;
  const a = points[0];
  const b = points[points.length - 1];
  const len = Math.hypot(b.x - a.x, b.z - a.z);
  let worst = 0;
  let at = 0;
  for (let i = 1; i < points.length - 1; i++) {
    const q = points[i];
    const d = len > 0 ? Math.abs((b.x - a.x) * (a.z - q.z) - (a.x - q.x) * (b.z - a.z)) / len : Math.hypot(q.x - a.x, q.z - a.z);
    if (d > worst) [worst, at] = [d, i];
  }
  if (worst <= tolerance) return [a, b];
  return [...douglasPeucker(points.slice(0, at + 1), tolerance).slice(0, -1), ...douglasPeucker(points.slice(at), tolerance)];
}

/** An object's outline in plan coordinates (metres): its mesh's silhouette placed like the mesh. Empty for an unknown object. */
export function objectPolygons(config: Configuration, objectId: string): PlanPoint[][] {
  const o = config.objects.find((x) => x.id === objectId);
  const mesh = o && sourceMesh(config, o.source);
  if (!o || !mesh) return [];
  const place = placementTransform(objectPlacement(o, config.room));
  return meshOutline(mesh).map((loop) =>
    loop.map((q) => {
      const w = place(q.x, 0, q.z);
      return { x: w[0], z: w[2] };
    }),
  );
}
