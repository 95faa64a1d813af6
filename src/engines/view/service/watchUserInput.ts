/** Input that means the user is interacting (a hovering pointer does not count). */
const INPUT_EVENTS = ['pointerdown', 'pointermove', 'keydown', 'wheel', 'touchstart'] as const;

export interface UserInputWatch {
  /** How long bake work should still wait: until the input has been quiet for the quiet time, ms (0: go). */
  holdMs(): number;
  dispose(): void;
}

/** Watches `input` (capturing, passive) for the user's pointer, key, wheel and touch input; null: nothing to watch, never holds. */
export function watchUserInput(input: Pick<EventTarget, 'addEventListener' | 'removeEventListener'> | null, quietMs: number, clock: () => number): UserInputWatch {
  let lastInput = -Infinity;
  const onInput = (e: Event) => {
    if (e.type === 'pointermove' && (e as PointerEvent).buttons === 0) return;
    lastInput = clock();
  };
  const listen = { capture: true, passive: true };
  if (input) for (const type of INPUT_EVENTS) input.addEventListener(type, onInput, listen);
  return {
    holdMs: () => Math.max(0, lastInput + quietMs - clock()),
    dispose() {
      if (input) for (const type of INPUT_EVENTS) input.removeEventListener(type, onInput, listen);
    },
  };
}
