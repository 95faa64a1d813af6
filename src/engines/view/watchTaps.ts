/** Most a pointer may travel between press and release, CSS pixels, and still be a tap (a longer travel orbits the camera). */
export const TAP_SLOP_PX = 6;

/**
 * Taps and clicks on an element, told apart from the drags that orbit the camera: a primary
 * pointer released within TAP_SLOP_PX of where it went down, while no second pointer (a pinch)
 * joined. Reports the point in normalised device coordinates (−1…1, y up), what three's
 * Raycaster takes. Returns a function that stops listening.
 */
export function watchTaps(element: HTMLElement, onTap: (ndcX: number, ndcY: number) => void): () => void {
  const down = new Map<number, { x: number; y: number }>();
  let pinched = false;
  const onDown = (e: PointerEvent) => {
    if (e.button !== 0 && e.pointerType === 'mouse') return;
    down.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (down.size > 1) pinched = true;
  };
  const onUp = (e: PointerEvent) => {
    const start = down.get(e.pointerId);
    down.delete(e.pointerId);
    const wasPinch = pinched;
    if (down.size === 0) pinched = false;
    if (!start || wasPinch || Math.hypot(e.clientX - start.x, e.clientY - start.y) > TAP_SLOP_PX) return;
    const r = element.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) return;
    onTap(((e.clientX - r.left) / r.width) * 2 - 1, -(((e.clientY - r.top) / r.height) * 2 - 1));
  };
  const onCancel = (e: PointerEvent) => {
    down.delete(e.pointerId);
    if (down.size === 0) pinched = false;
  };
  element.addEventListener('pointerdown', onDown);
  element.addEventListener('pointerup', onUp);
  element.addEventListener('pointercancel', onCancel);
  return () => {
    element.removeEventListener('pointerdown', onDown);
    element.removeEventListener('pointerup', onUp);
    element.removeEventListener('pointercancel', onCancel);
  };
}
