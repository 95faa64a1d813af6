/**
 * A trackpad pinch has no fingers to measure: it is handed to the controller as a pinch whose
 * distance starts at this many pixels and follows the gesture's scale (the controller only uses
 * ratios of distances).
 */
export const TRACKPAD_PINCH_SPAN_PX = 100;

/**
 * ctrl+wheel deltaY per e-fold of scale. Chromium sends a trackpad pinch as ctrl+wheel events with
 * deltaY = −100·ln(scale) per event, designed so that deltas add (components/input/
 * touchpad_pinch_event_queue.cc: "to convert a wheel deltaY back to a scale use
 * Math.exp(-deltaY/100)"); Firefox sends deltaY = −100·M from macOS's magnification M
 * (PinchGestureInput::ComputeDeltaY, widget/InputData.cpp), the same to first order. So the
 * pinch's scale is exp(−ΣdeltaY / 100) over the gesture's events. (@use-gesture recognises the
 * gesture, its start, end and centre; its own scale, offset·(1 − deltaY/100) per event, reaches
 * zero for one ctrl+mouse-wheel notch of 100 px.)
 */
export const CTRL_WHEEL_PX_PER_E = 100;

/**
 * One ctrl+wheel event changes the scale by at most e^(±0.5) (×1.65): a trackpad sends a few
 * pixels per event, but a mouse wheel turned with ctrl held sends 100 or more per notch, which
 * would otherwise zoom ×2.7 at a click.
 */
export const CTRL_WHEEL_MAX_DELTA_PX = 50;

/** Pixels per line and per page for wheels that count lines (deltaMode 1) or pages (deltaMode 2), as @use-gesture converts them. */
export const WHEEL_LINE_PX = 40;
export const WHEEL_PAGE_PX = 800;

/** A wheel's vertical delta in pixels, whatever unit the browser counted in. */
export function wheelPixels(deltaY: number, deltaMode: number): number {
  if (deltaMode === 1) return deltaY * WHEEL_LINE_PX;
  if (deltaMode === 2) return deltaY * WHEEL_PAGE_PX;
  return deltaY;
}

/** The ctrl+wheel deltas of one trackpad pinch, summed with each event clamped (CTRL_WHEEL_MAX_DELTA_PX). */
export function addWheelPinchDelta(sumPx: number, deltaYPixels: number): number {
  return sumPx + Math.max(-CTRL_WHEEL_MAX_DELTA_PX, Math.min(CTRL_WHEEL_MAX_DELTA_PX, deltaYPixels));
}

/** The span handed to the controller for a trackpad pinch whose clamped deltas add up to `sumPx`. */
export function wheelPinchSpan(sumPx: number): number {
  return TRACKPAD_PINCH_SPAN_PX * Math.exp(-sumPx / CTRL_WHEEL_PX_PER_E);
}
