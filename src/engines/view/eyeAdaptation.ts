/**
 * Automatic exposure that adapts like an eye and holds while the light is only changed
 * (docs/viewer.md, "Exposure that compares"):
 *
 * - **Slowly**: towards a new target the adapting level moves exponentially in log luminance,
 *   L(t) = L_target · (L_from / L_target)^exp(−t/τ), the first-order model of visual adaptation
 *   over time (Pattanaik, Tumblin, Yee, Greenberg, "Time-dependent visual adaptation for fast
 *   realistic image display", SIGGRAPH 2000; the exponential form and τ as used by Krawczyk,
 *   Myszkowski, Seidel, "Perceptual effects in real-time tone mapping", SCCG 2005, eq. 4: τ ≈
 *   0.1 s for cones, 0.4 s for rods). The viewer takes τ = 0.4 s: a cut to another room is
 *   seen to settle within about a second and a half (4τ), yet no step stays on screen. The adopted
 *   white follows with the same τ.
 * - **Within limits**: the automatic exposure is kept between EV100 AUTO_EV100_MIN and
 *   AUTO_EV100_MAX (photographicExposure.ts): a room darker than L̄ ≈ 0.2 cd/m² (about 1.5 lx
 *   on a ρ 0.5 floor) is shown darker than middle grey, as night vision cannot make it look bright.
 * - **Held**: it follows the maps of a configuration until that configuration's light is done,
 *   then holds, so dimming, a light-scene crossfade, a filter or DMX (relights: the same room,
 *   objects and module positions, `key`) make the picture darker or brighter. A new key (room,
 *   objects or modules moved, added, removed) or `reAdapt()` (a camera preset, the Re-adapt
 *   button) adapts to the current maps again.
 */
import type { Vec3 } from './colourMatrices';
import { ev100FromExposure, exposureFromEv100 } from './photographicExposure';

/** Time constant of the adaptation (s): the rods' τ of Krawczyk et al. 2005. */
export const ADAPTATION_TAU_S = 0.4;
/** Limits of the automatic exposure (EV100). */
export const AUTO_EV100_MIN = 0;
export const AUTO_EV100_MAX = 15;

/** What the display adapts to: the automatic exposure (1/(cd/m²)) and the scene's adopted white (linear sRGB, luminance 1; null: none). */
export interface AdaptationState {
  auto: number;
  white: Vec3 | null;
}

/** The automatic exposure kept within AUTO_EV100_MIN..AUTO_EV100_MAX; a non-finite or non-positive one counts as 1. */
export function limitAutoExposure(auto: number): number {
  const a = Number.isFinite(auto) && auto > 0 ? auto : 1;
  const ev = Math.min(AUTO_EV100_MAX, Math.max(AUTO_EV100_MIN, ev100FromExposure(a)));
  return exposureFromEv100(ev);
}

export interface EyeAdaptation {
  /**
   * New maps with their own target state. `key` names the geometry (room, objects, module
   * positions): the same key once `done` was seen is a relight and holds.
   */
  update(target: AdaptationState, key: string, done: boolean, nowMs: number): void;
  /** Adapt to the last maps' target again (camera cut, the Re-adapt button). */
  reAdapt(nowMs: number): void;
  /** The state to display at `nowMs` (null before any maps). */
  state(nowMs: number): AdaptationState | null;
  /** Whether the state still moves at `nowMs` (the view keeps drawing frames until it does not). */
  moving(nowMs: number): boolean;
  /** Whether new maps of the current key are held (its light was done). */
  readonly held: boolean;
}

/** Below this remaining log-distance (≈ 0.01 EV) the state snaps to its target. */
const SETTLED_LOG = 0.007;

export function createEyeAdaptation(tauS: number = ADAPTATION_TAU_S): EyeAdaptation {
  const tauMs = Math.max(1e-3, tauS * 1000);
  let key: string | null = null;
  let held = false;
  let from: AdaptationState | null = null;
  let to: AdaptationState | null = null;
  let startMs = 0;
  let latest: AdaptationState | null = null;

  const progress = (nowMs: number): number => {
    if (!from || !to) return 1;
    const k = Math.exp(-Math.max(0, nowMs - startMs) / tauMs);
    const distance = Math.abs(Math.log(from.auto / to.auto)) * k;
    const whiteDistance = from.white && to.white ? Math.max(...from.white.map((v, i) => Math.abs(v - to!.white![i]))) * k : 0;
    return distance < SETTLED_LOG && whiteDistance < SETTLED_LOG ? 1 : 1 - k;
  };
  const state = (nowMs: number): AdaptationState | null => {
    if (!to) return null;
    const p = progress(nowMs);
    if (p >= 1 || !from) return to;
    const auto = Math.exp(Math.log(from.auto) + (Math.log(to.auto) - Math.log(from.auto)) * p);
    const white = from.white && to.white ? (from.white.map((v, i) => v + (to!.white![i] - v) * p) as unknown as Vec3) : to.white;
    return { auto, white };
  };
  const retarget = (target: AdaptationState, nowMs: number) => {
    const current = state(nowMs);
    from = current;
    to = { auto: limitAutoExposure(target.auto), white: target.white };
    startMs = nowMs;
  };

  return {
    update(target, nextKey, done, nowMs) {
      latest = target;
      if (nextKey !== key) {
        key = nextKey;
        held = false;
      }
      if (!held) retarget(target, nowMs);
      if (done) held = true;
    },
    reAdapt(nowMs) {
      if (latest) retarget(latest, nowMs);
    },
    state,
    moving(nowMs) {
      return !!to && !!from && progress(nowMs) < 1;
    },
    get held() {
      return held;
    },
  };
}
