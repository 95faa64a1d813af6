import { useLayoutEffect, type RefObject } from 'react';

/** Whether `el` or one of its buttons is wider than its box: a label cut off or the bar scrolling. */
export function overflows(el: HTMLElement): boolean {
  if (el.scrollWidth > el.clientWidth) return true;
  for (const b of el.querySelectorAll<HTMLElement>('button')) if (b.scrollWidth > b.clientWidth) return true;
  return false;
}

/**
 * Every language fits every phone (docs/accessibility.md, "Narrow phones"): a bar whose controls do
 * not fit its width with their full labels gets `data-compact`, and its CSS shows them as icons
 * (each keeps its full name in aria-label and title). Measured, not guessed from the language or
 * the width: the text is laid out with the real font, and it is measured again whenever the bar's
 * size or its text changes (a price getting longer, another language, 2D ↔ 3D).
 */
export function useFitCompact(ref: RefObject<HTMLElement | null>): void {
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el) return;
    const fit = () => {
      // Measure with the full labels, then decide; both in the same frame, before it is painted.
      if (el.dataset.compact !== undefined) delete el.dataset.compact;
      if (overflows(el)) el.dataset.compact = '';
    };
    fit();
    const ro = new ResizeObserver(fit);
    ro.observe(el);
    // Text changes inside the bar (not attribute changes: the flag itself must not trigger a new measure).
    const mo = new MutationObserver(fit);
    mo.observe(el, { subtree: true, childList: true, characterData: true });
    return () => {
      ro.disconnect();
      mo.disconnect();
    };
  }, [ref]);
}
