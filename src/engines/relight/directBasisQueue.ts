import type { BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import type { BakeJob, Baker, DirectMaps } from '../bake/createBaker';
import type { GroupState } from './groupState';
import type { LuminaireGroup } from './luminaireGroups';
import { startDaylightBasisJob } from './startDaylightBasisJob';

/** The direct bases still to bake, one group at a time in two steps (issue, then read back). */
export interface DirectBasisQueue {
  /**
   * Issues the next group without a basis, or reads back the one issued last call (handing its
   * maps to `onBasis`). False when every group of `order` has its basis: nothing was done.
   */
  advance(scene: BakeScene, order: readonly GroupState[], states: ReadonlyMap<string, GroupState>): boolean;
  /** Drops a basis under way for a group that is no longer among `states` (moved, removed). */
  keepOnly(states: ReadonlyMap<string, GroupState>): void;
  /** Drops the basis under way, if any. */
  drop(): void;
}

/** One group's basis scene: the room, the group's luminaires at unit weight, and the scene's objects (they shade every group's light). */
export function groupScene(scene: BakeScene, group: LuminaireGroup): BakeScene {
  return { room: scene.room, luminaires: group.basis, ...(scene.objects && scene.objects.length > 0 ? { objects: scene.objects } : {}) };
}

/**
 * Bakes direct bases with `basisSettings` (no bounces). A basis takes two steps: the first issues
 * the GPU work (draws return at once: in a browser the GPU process runs them), the second reads the
 * maps back. The caller's slicer fences between steps (createBakeSlicer), so the read-back finds
 * the work done instead of blocking the page while a software GPU runs a furnished room's
 * shadowed direct passes (seconds on SwiftShader). A daylight group (daylightGroups.ts) computes
 * its direct daylight on the CPU in the first step (startDaylightBasisJob.ts). `onStart` counts each basis started;
 * `onBasis` receives the maps of a group that still wants them.
 */
export function createDirectBasisQueue(baker: Baker, basisSettings: BakeSettings, onStart: (group: LuminaireGroup) => void, onBasis: (state: GroupState, direct: DirectMaps) => void): DirectBasisQueue {
  /** A direct basis whose passes are issued but not read back yet. */
  let pending: { key: string; job: BakeJob } | null = null;
  const drop = () => {
    pending?.job.dispose();
    pending = null;
  };
  const readBack = (states: ReadonlyMap<string, GroupState>, { key, job }: { key: string; job: BakeJob }) => {
    try {
      const st = states.get(key);
      if (st && !st.basis) onBasis(st, job.readDirect());
    } finally {
      job.dispose();
    }
  };
  return {
    advance(scene, order, states) {
      if (pending) {
        const issued = pending;
        pending = null;
        readBack(states, issued);
        return true;
      }
      const st = order.find((s) => !s.basis);
      if (!st) return false;
      onStart(st.group);
      const { daylight } = st.group;
      const job = daylight ? startDaylightBasisJob(baker, scene, daylight, basisSettings) : baker.start(groupScene(scene, st.group), basisSettings);
      try {
        // Everything up to the read-back (objects: chart dilation of the atlas) is issued now.
        job.finalize();
      } catch (error) {
        job.dispose();
        throw error;
      }
      pending = { key: st.group.key, job };
      return true;
    },
    keepOnly(states) {
      if (pending && !states.has(pending.key)) drop();
    },
    drop,
  };
}
