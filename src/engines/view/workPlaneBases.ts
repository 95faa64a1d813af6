import { bilinearRgb } from '../bake/bilinearMap';
import type { BakeScene } from '../bake/bakeScene';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { DirectBasis, IndirectSolution } from '../relight/relightMaps';
import { workPlaneDirect, workPlaneUnderObjects } from './lightStats';

/** The work plane of a box room as the statistics take it: nx × nz cell centres at `height`, and the points left out (workPlaneUnderObjects). */
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

/** Work-plane part grids for a box room (`scene.room.shape` unset: a shaped room's plane follows its outline, shapedWorkPlaneStats.ts). */
export function createWorkPlaneBases(scene: BakeScene, height: number, spacing = 0.1, objects: PreparedObjects | null = null): WorkPlaneBases {
  if (scene.room.shape) throw new Error('work-plane bases: a shaped room has its work plane over its outline (shapedWorkPlaneStats)');
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
