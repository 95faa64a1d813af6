/**
 * Follows a canvas's WebGL context through loss and restore. The loss event's
 * default is prevented: that is what tells the browser we want the context
 * back (a `webglcontextrestored` follows).
 */
export interface ContextWatch {
  /** Lost and not yet restored. */
  readonly lost: boolean;
  /** Stop listening. */
  dispose(): void;
}

export function watchContextLoss(canvas: HTMLCanvasElement, on: { lost(): void; restored(): void }): ContextWatch {
  let lost = false;
  const onLost = (e: Event) => {
    e.preventDefault();
    lost = true;
    on.lost();
  };
  const onRestored = () => {
    lost = false;
    on.restored();
  };
  canvas.addEventListener('webglcontextlost', onLost);
  canvas.addEventListener('webglcontextrestored', onRestored);
  return {
    get lost() {
      return lost;
    },
    dispose() {
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
    },
  };
}
