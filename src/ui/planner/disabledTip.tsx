import { createContext, useCallback, useContext, useEffect, useLayoutEffect, useMemo, useRef, useState, type RefObject } from 'react';
import type { RemedyOffer } from './actionGate';
import { useI18n } from '../i18n/useI18n';

/** Shows a disabled control's reason at the control (issue 27, docs/planner.md "Reasons at the control"). */
export interface DisabledTipApi {
  show(reason: string, anchor: HTMLElement, remedy: RemedyOffer | null): void;
}

export const DisabledTipContext = createContext<DisabledTipApi | null>(null);

/** The planner's tip, or null outside a planner (tests rendering a control alone: the status line still explains). */
export function useDisabledTip(): DisabledTipApi | null {
  return useContext(DisabledTipContext);
}

export interface TipState {
  reason: string;
  remedy: RemedyOffer | null;
  /** The anchor's box in the layer's coordinates (px). */
  anchor: { left: number; top: number; width: number; height: number };
  /** The layer's size, to keep the tip inside it. */
  layer: { width: number; height: number };
  seq: number;
}

/** The state and API of one tip layer: `layerRef` is the positioned element the tip is placed in. */
export function useDisabledTipState(layerRef: RefObject<HTMLElement | null>): [TipState | null, DisabledTipApi, () => void] {
  const [tip, setTip] = useState<TipState | null>(null);
  const api = useMemo<DisabledTipApi>(() => {
    let seq = 0;
    return {
      show(reason, anchor, remedy) {
        const layer = layerRef.current;
        if (!layer) return;
        const l = layer.getBoundingClientRect();
        const a = anchor.getBoundingClientRect();
        setTip({ reason, remedy, anchor: { left: a.left - l.left, top: a.top - l.top, width: a.width, height: a.height }, layer: { width: l.width, height: l.height }, seq: ++seq });
      },
    };
  }, [layerRef]);
  const close = useCallback(() => setTip(null), []);
  return [tip, api, close];
}

const GAP = 8;
const MARGIN = 8;

/**
 * The tip itself: the reason in the UI language (role=status, so screen readers hear it), the
 * remedy as a button when there is one, and a close button. Placed under the control, or above it
 * when there is more room there, kept inside the layer. Escape or a press elsewhere dismisses it;
 * one without a remedy also goes after 8 s.
 */
export function DisabledTip({ tip, onClose }: { tip: TipState; onClose: () => void }) {
  const { t } = useI18n();
  const ref = useRef<HTMLDivElement>(null);
  const [pos, setPos] = useState<{ left: number; top: number } | null>(null);
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el) return;
    const w = el.offsetWidth;
    const h = el.offsetHeight;
    const { anchor, layer } = tip;
    const below = anchor.top + anchor.height + GAP;
    const above = anchor.top - GAP - h;
    const top = below + h <= layer.height - MARGIN || above < MARGIN ? below : above;
    const left = Math.min(Math.max(MARGIN, anchor.left + anchor.width / 2 - w / 2), Math.max(MARGIN, layer.width - w - MARGIN));
    setPos({ left, top: Math.max(MARGIN, Math.min(top, layer.height - h - MARGIN)) });
  }, [tip]);
  useEffect(() => {
    const key = (e: KeyboardEvent) => {
      if (e.key === 'Escape') onClose();
    };
    const press = (e: PointerEvent) => {
      if (ref.current && !ref.current.contains(e.target as Node)) onClose();
    };
    window.addEventListener('keydown', key);
    window.addEventListener('pointerdown', press, true);
    const timer = tip.remedy ? undefined : window.setTimeout(onClose, 8000);
    return () => {
      window.removeEventListener('keydown', key);
      window.removeEventListener('pointerdown', press, true);
      if (timer !== undefined) window.clearTimeout(timer);
    };
  }, [tip, onClose]);
  return (
    <div ref={ref} className="disabled-tip" role="status" data-testid="disabled-tip" data-plan-control style={pos ? { left: pos.left, top: pos.top } : { left: 0, top: 0, visibility: 'hidden' }}>
      <p className="disabled-tip-reason">{tip.reason}</p>
      <div className="disabled-tip-actions">
        {tip.remedy && (
          <button
            type="button"
            className="btn btn-primary"
            data-testid="remedy"
            onClick={() => {
              tip.remedy?.run();
              onClose();
            }}
          >
            {tip.remedy.label}
          </button>
        )}
        <button type="button" className="btn" onClick={onClose} data-testid="disabled-tip-close">
          {t('common.close')}
        </button>
      </div>
    </div>
  );
}
