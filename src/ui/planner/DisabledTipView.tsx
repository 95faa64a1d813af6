import { useEffect, useLayoutEffect, useRef, useState } from 'react';
import { useStore } from 'zustand';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { remedyOffer } from './remedyOffer';
import { reasonBesideRemedy } from './remedyReason';
import { REFUSED_EVENT, type RefusedDetail, type TipState } from './disabledTip';
import { useI18n } from '../i18n/useI18n';

const GAP = 8;
const MARGIN = 8;

/**
 * The tip itself: the reason in the UI language (role=status, so screen readers hear it), the
 * remedy as a button when there is one, and a close button. Placed under the control, or above it
 * when there is more room there, kept inside the element it is placed in (the planner's workspace). Escape or a press elsewhere dismisses it;
 * one without a remedy also goes after 8 s.
 */
export function DisabledTip({ tip, onClose, store, explain }: { tip: TipState; onClose: () => void; store: ConfiguratorStore; explain: (reason: string) => void }) {
  const i18n = useI18n();
  const { t } = i18n;
  const ref = useRef<HTMLDivElement>(null);
  const [pos, setPos] = useState<{ left: number; top: number } | null>(null);
  // What would make the refused action enabled, worked out once for this press.
  const [remedy] = useState(() => (tip.action ? remedyOffer(store, tip.action.name, tip.action.params, i18n, explain) : null));
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el) return;
    const w = el.offsetWidth;
    const h = el.offsetHeight;
    // The control's box in the coordinates of the element the tip is placed in (the workspace).
    const l = (el.offsetParent ?? document.body).getBoundingClientRect();
    const a = tip.target.getBoundingClientRect();
    const anchor = { left: a.left - l.left, top: a.top - l.top, width: a.width, height: a.height };
    const layer = { width: l.width, height: l.height };
    const below = anchor.top + anchor.height + GAP;
    const above = anchor.top - GAP - h;
    const top = below + h <= layer.height - MARGIN || above < MARGIN ? below : above;
    const left = Math.min(Math.max(MARGIN, anchor.left + anchor.width / 2 - w / 2), Math.max(MARGIN, layer.width - w - MARGIN));
    setPos({ left, top: Math.max(MARGIN, Math.min(top, layer.height - h - MARGIN)) });
  }, [tip, remedy]);
  useEffect(() => {
    const key = (e: KeyboardEvent) => {
      if (e.key === 'Escape') onClose();
    };
    const press = (e: PointerEvent) => {
      if (ref.current && !ref.current.contains(e.target as Node)) onClose();
    };
    window.addEventListener('keydown', key);
    window.addEventListener('pointerdown', press, true);
    const timer = remedy ? undefined : window.setTimeout(onClose, 8000);
    return () => {
      window.removeEventListener('keydown', key);
      window.removeEventListener('pointerdown', press, true);
      if (timer !== undefined) window.clearTimeout(timer);
    };
  }, [tip, remedy, onClose]);
  return (
    <div ref={ref} className="disabled-tip" role="status" data-testid="disabled-tip" data-plan-control style={pos ? { left: pos.left, top: pos.top } : { left: 0, top: 0, visibility: 'hidden' }}>
      <p className="disabled-tip-reason">{remedy ? reasonBesideRemedy(tip.reason) : tip.reason}</p>
      <div className="disabled-tip-actions">
        {remedy && (
          <button
            type="button"
            className="btn btn-primary"
            data-testid="remedy"
            onClick={() => {
              remedy.run();
              onClose();
            }}
          >
            {remedy.label}
          </button>
        )}
        <button type="button" className="btn" onClick={onClose} data-testid="disabled-tip-close">
          {t('common.close')}
        </button>
      </div>
    </div>
  );
}

/**
 * Listens for refused presses in the element it is placed in (the planner's workspace) and shows
 * the tip at the pressed control; the tip goes when the configuration changes (the control may
 * move or change) or the plan is left for the 3D view.
 */
export function TipHost({ store, mode, explain }: { store: ConfiguratorStore; mode: '2d' | '3d'; explain: (reason: string) => void }) {
  const ref = useRef<HTMLSpanElement>(null);
  const [pressed, setPressed] = useState<TipState | null>(null);
  const config = useStore(store, (s) => s.config);
  useEffect(() => {
    const layer = ref.current?.parentElement;
    let seq = 0;
    const show = (e: Event) => {
      e.preventDefault();
      setPressed({ ...(e as CustomEvent<RefusedDetail>).detail, target: e.target as Element, config: store.getState().config, seq: ++seq });
    };
    layer?.addEventListener(REFUSED_EVENT, show);
    // Says when refused presses reach the tip (tests wait for it: the host listens only after its effect ran).
    ref.current?.setAttribute('data-listening', '');
    return () => layer?.removeEventListener(REFUSED_EVENT, show);
  }, [store]);
  const tip = pressed && pressed.config === config && mode === '2d' ? pressed : null;
  return (
    <>
      <span ref={ref} hidden data-testid="tip-host" />
      {tip && <DisabledTip key={tip.seq} tip={tip} onClose={() => setPressed(null)} store={store} explain={explain} />}
    </>
  );
}
