/**
 * The one place that converts between screen pixels and world metres in the plan.
 *
 * The plan is the room seen from above (docs/scene-format.md "Units and frames"): plan x =
 * world x, plan y (SVG, pointing down) = world z. A view is a uniform scale plus an
 * offset, so the mapping is
 *
 *   screenX = worldX · scale + offsetX
 *   screenY = worldZ · scale + offsetY
 *
 * with `scale` in pixels per metre. Everything else in the planner (hit tests, the
 * positions of on-screen controls, zoom about the cursor) goes through these functions.
 */

/** A point in the plan in metres: x = world x, z = world z. */
export interface PlanPoint {
  x: number;
  z: number;
}

/** A point on screen in CSS pixels relative to the plan's top-left corner. */
export interface ScreenPoint {
  sx: number;
  sy: number;
}

export interface PlanView {
  /** CSS pixels per metre. */
  scale: number;
  offsetX: number;
  offsetY: number;
}

export interface Viewport {
  width: number;
  height: number;
}

/** Zoom limits in pixels per metre: a 50 m hall still fits on a phone; a 5 cm detail fills it. */
export const MIN_SCALE = 4;
export const MAX_SCALE = 4000;

export function clampScale(scale: number): number {
  if (!Number.isFinite(scale)) return MIN_SCALE;
  return Math.min(MAX_SCALE, Math.max(MIN_SCALE, scale));
}

export function worldToScreen(view: PlanView, p: PlanPoint): ScreenPoint {
  return { sx: p.x * view.scale + view.offsetX, sy: p.z * view.scale + view.offsetY };
}

export function screenToWorld(view: PlanView, s: ScreenPoint): PlanPoint {
  return { x: (s.sx - view.offsetX) / view.scale, z: (s.sy - view.offsetY) / view.scale };
}

/** A length in metres as CSS pixels at this view. */
export function metresToPixels(view: PlanView, metres: number): number {
  return metres * view.scale;
}

/** A length in CSS pixels as metres at this view. */
export function pixelsToMetres(view: PlanView, pixels: number): number {
  return pixels / view.scale;
}

/** Free space around a fitted room: 6 % of the short side, 16–48 px (a phone keeps its plan large). */
export function fitMargin(viewport: Viewport): number {
  return Math.round(Math.min(48, Math.max(16, Math.min(viewport.width, viewport.height) * 0.06)));
}

/**
 * The view that shows the whole room (width × depth metres) centred in the viewport with
 * `marginPx` free on every side, so the walls and the controls drawn outside them stay visible.
 */
export function fitRoom(room: { width: number; depth: number }, viewport: Viewport, marginPx = fitMargin(viewport)): PlanView {
  const availW = Math.max(1, viewport.width - 2 * marginPx);
  const availH = Math.max(1, viewport.height - 2 * marginPx);
  const scale = clampScale(Math.min(availW / room.width, availH / room.depth));
  return {
    scale,
    offsetX: (viewport.width - room.width * scale) / 2,
    offsetY: (viewport.height - room.depth * scale) / 2,
  };
}

/**
 * Zoom by `factor` keeping the world point under `anchor` fixed on screen (zoom about the
 * cursor or the pinch centre, as map services do). The factor is clamped so the scale stays
 * within [MIN_SCALE, MAX_SCALE]; the anchor stays fixed even when clamped.
 */
export function zoomAt(view: PlanView, anchor: ScreenPoint, factor: number): PlanView {
  const scale = clampScale(view.scale * factor);
  const w = screenToWorld(view, anchor);
  return { scale, offsetX: anchor.sx - w.x * scale, offsetY: anchor.sy - w.z * scale };
}

/** The same view moved by a screen-space delta (dragging the plan). */
export function panBy(view: PlanView, dx: number, dy: number): PlanView {
  return { scale: view.scale, offsetX: view.offsetX + dx, offsetY: view.offsetY + dy };
}

/**
 * A view that puts the world point `center` in the middle of the viewport at `scale`
 * (zooming onto a selected system).
 */
export function centerOn(center: PlanPoint, scale: number, viewport: Viewport): PlanView {
  const s = clampScale(scale);
  return { scale: s, offsetX: viewport.width / 2 - center.x * s, offsetY: viewport.height / 2 - center.z * s };
}

/**
 * Wheel delta (pixels, after normalising line/page modes) to a zoom factor. exp() makes
 * zooming in then out by the same wheel distance return exactly to the start, and keeps
 * the zoom stepless for trackpads that send many small deltas.
 */
export function wheelZoomFactor(deltaYPixels: number): number {
  const d = Math.max(-500, Math.min(500, deltaYPixels));
  return Math.exp(-d / 400);
}

/** Keep at least `keepPx` of the room on screen so the user can never pan it out of reach. */
export function constrainPan(view: PlanView, room: { width: number; depth: number }, viewport: Viewport, keepPx = 64): PlanView {
  const roomW = room.width * view.scale;
  const roomH = room.depth * view.scale;
  const minX = keepPx - roomW;
  const maxX = viewport.width - keepPx;
  const minY = keepPx - roomH;
  const maxY = viewport.height - keepPx;
  return {
    scale: view.scale,
    offsetX: Math.min(maxX, Math.max(minX, view.offsetX)),
    offsetY: Math.min(maxY, Math.max(minY, view.offsetY)),
  };
}
