import { bilinearRgb } from '../bake/bilinearMap';
import type { BakeScene } from '../bake/bakeScene';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { DirectBasis, IndirectSolution } from '../relight/relightMaps';
import { workPlaneDirect, workPlaneUnderObjects } from './lightStats';
import { shapedWorkPlaneDirect, shapedWorkPlaneGrid } from './shapedWorkPlaneStats';

/** The work plane as the statistics take it: nx × nz cell centres at `height`, and the points left out (a box room: workPlaneUnderObjects; a shaped room: outside its outline). */
export interface WorkPlaneGrid {
  height: number;
  nx: number;
  nz: number;
  /** 1 where the point lies inside furniture standing on the floor (left out of the statistics), row-major. */
  covered: Uint8Array;
}

/**
 * The work plane's light per relight part (docs/viewer.md, "Work-plane statistics on the GPU"). The
 * CPU formula (lightStats.ts workPlaneStats) is E(p) = Y(direct(p)) + max(0, Y(floorTotal(p) −
 * floorDirect(p))) with bilinear floor lookups. Its direct part is a sum over the luminaires, so it is
 * Σ_g w_g ⊙ direct_g(p) with each group's basis luminaires (unit dimming, white) and the relight's
 * weights. Its indirect part is the floor's total minus its direct, which relightMaps.ts makes
 * Σ_k s_k ⊙ indirect_k exactly; bilinear lookup is linear, so it is Σ_k s_k ⊙ bilinear(indirect_k)(p).
 * Both are linear in the same weights and scales the display maps are combined with. The max(0, ·)
 * only guards the float cancellation of total − direct: the indirect solutions are gathered light,
 * never negative, and the scales are ≥ 0. So `direct(basis)` and `indirect(solution)` are grids
 * (RGB per point, row-major like the statistics) the GPU combine weighs like any other map.
 * Each is computed once per basis or solution on the CPU (cached by object identity) for the
 * grid in force; another height, spacing, scene room or objects makes a fresh set.
 */
export interface WorkPlaneBases {
  readonly grid: WorkPlaneGrid;
  /** The basis's direct light at the grid points, or null when the basis does not carry its luminaires. */
  direct(basis: DirectBasis): Float32Array | null;
  /** The solution's floor indirect light at the grid points' plan positions. */
  indirect(solution: IndirectSolution, floor: SurfaceLayout): Float32Array;
}

/**
 * A room of any shape: the grid over its outline (shapedWorkPlaneGrid), each basis's direct light
 * (its luminaires in the enclosure's coordinates, as the engine baked them) with the shadows of the room's own surfaces and the objects, each solution's indirect light from
 * the atlas texel under the point: the atlas's total − direct is Σ_k s_k ⊙ objects_k (relightMaps.ts),
 * so the CPU's max(0, Y(total − direct)) at that texel is Σ_k s_k ⊙ this grid, as on the box's floor.
 * `objects`: the enclosure's prepared objects (the room's surfaces first), as the atlas was laid out.
 */
function createShapedWorkPlaneBases(scene: BakeScene, height: number, spacing: number, objects: PreparedObjects | null): WorkPlaneBases {
  const grid = shapedWorkPlaneGrid(scene, height, spacing, objects);
  const directs = new WeakMap<DirectBasis, Float32Array>();
  const indirects = new WeakMap<IndirectSolution, Float32Array>();
  return {
    grid,
    direct(basis) {
      if (!basis.luminaires) return null;
      let d = directs.get(basis);
      if (!d) directs.set(basis, (d = shapedWorkPlaneDirect(scene, grid, basis.luminaires, true)));
      return d;
    },
    indirect(solution) {
      let d = indirects.get(solution);
      if (!d) {
        d = new Float32Array(grid.nx * grid.nz * 3);
        const atlas = solution.objects;
        for (let n = 0; atlas && n < grid.nx * grid.nz; n++) {
          const t = grid.floorTexel[n];
          if (t >= 0 && !grid.covered[n]) d.set(atlas.subarray(3 * t, 3 * t + 3), 3 * n);
        }
        indirects.set(solution, d);
      }
      return d;
    },
  };
}

/** Work-plane part grids for a box room, or for a room of any shape over its outline (createShapedWorkPlaneBases). */
export function createWorkPlaneBases(scene: BakeScene, height: number, spacing = 0.1, objects: PreparedObjects | null = null): WorkPlaneBases {
  if (scene.room.shape) return createShapedWorkPlaneBases(scene, height, spacing, objects);
  const { width, depth } = scene.room;
  const nx = Math.max(1, Math.round(width / spacing));
  const nz = Math.max(1, Math.round(depth / spacing));
  const grid: WorkPlaneGrid = { height, nx, nz, covered: workPlaneUnderObjects(scene.room, nx, nz, height, objects) };
  const directs = new WeakMap<DirectBasis, Float32Array>();
  const indirects = new WeakMap<IndirectSolution, Float32Array>();
  return {
    grid,
    direct(basis) {
      if (!basis.luminaires) return null;
      let d = directs.get(basis);
      if (!d) directs.set(basis, (d = workPlaneDirect(scene, basis.luminaires, height, nx, nz, {}, objects)));
      return d;
    },
    indirect(solution, floor) {
      let d = indirects.get(solution);
      if (!d) {
        d = new Float32Array(nx * nz * 3);
        const map = solution.surfaces.floor;
        for (let k = 0; k < nz; k++) for (let i = 0; i < nx; i++) d.set(bilinearRgb(floor, map, ((i + 0.5) / nx) * width, ((k + 0.5) / nz) * depth), (k * nx + i) * 3);
        indirects.set(solution, d);
      }
      return d;
    },
  };
}
