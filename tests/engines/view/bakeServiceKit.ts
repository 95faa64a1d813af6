/**
 * What the bake-service tests share (bakeSlicer, bakeService, bakeStalls): a hand-run stand-in for
 * setTimeout, a two-lamp room, and a service on its own headless-gl context.
 */
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBakeService, type BakeServiceOptions } from '../../../src/engines/view/createBakeService';
import { createHeadlessGL } from '../../../src/hosts/node/createHeadlessGL';
import { isotropic, uniformRoom } from '../bake/bakeTestKit';

/** Blocks the thread for `ms` (a GPU behind a fence keeps working meanwhile). */
const sleep = (ms: number) => Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);

/**
 * setTimeout stand-in: callbacks wait until run one at a time (each run may queue more). With
 * `realDelays` a callback queued with a delay runs after sleeping that long, as a real timer
 * would (fence polls on a real GPU need real time to pass).
 */
export function manualQueue(realDelays = false) {
  const pending: [() => void, number][] = [];
  return {
    defer: (f: () => void, ms = 0) => {
      pending.push([f, ms]);
    },
    get size() {
      return pending.length;
    },
    /** Runs queued callbacks (and those they queue) until none is left or `limit` ran; returns how many ran. */
    drain(limit = 100_000) {
      let n = 0;
      while (pending.length > 0 && n < limit) {
        const [f, ms] = pending.shift()!;
        if (realDelays && ms > 0) sleep(ms);
        f();
        n++;
      }
      return n;
    },
  };
}

export type ManualQueue = ReturnType<typeof manualQueue>;

/** A 3 × 2.5 × 3 m room of reflectance 0.5. */
export const room = uniformRoom(3, 2.5, 3, 0.5);
// One photometry object: groups are keyed by photometry identity (luminaireGroups).
const source = isotropic(300);
/** An isotropic 300 cd lamp at 2.3 m, full and white. */
export const lum = (x: number, z: number) => ({ photometry: source, position: [x, 2.3, z] as [number, number, number], yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] as [number, number, number] });
/** Two lamps in the room: two luminaire groups. */
export const scene: BakeScene = { room, luminaires: [lum(1, 1), lum(2, 2)] };

/**
 * A service at 'fast' quality on its own headless-gl context (disposing the service loses that
 * context), deferring to `q`; `options` as createBakeService takes them (the page, low memory, a clock, the fence).
 */
export function headlessBakeService(q: ManualQueue, options: Pick<BakeServiceOptions, 'visibility' | 'lowMemory' | 'now' | 'fence'>) {
  const gl = createHeadlessGL();
  const canvas = () => ({ getContext: () => gl, addEventListener: () => {}, removeEventListener: () => {} });
  const s = createBakeService({ quality: 'fast', input: null, canvas, defer: q.defer, ...options });
  return {
    s,
    dispose: () => {
      s.dispose();
      gl.destroy();
    },
  };
}
