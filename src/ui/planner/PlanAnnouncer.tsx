import { useEffect, useRef, useState } from 'react';
import type { ConfiguratorState, ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { useI18n } from '../i18n/useI18n';
import type { AnnouncedState, AnnounceContext } from './planAnnouncement';
// The touch-target and screen-reader-only rules (docs/accessibility.md) load with the planner.
import '../app/accessibility.css';

type Announce = typeof import('./planAnnouncement').announcement;

// The sentences (planAnnouncement.ts and their English) are a chunk of their own, outside the first
// screen (docs/benchmarks.md, "First screen"): fetched in idle time, as nothing is announced before
// the first change; a change before it arrives is announced when it has.
let announce: Announce | null = null;
let loading: Promise<Announce> | null = null;
function loadAnnouncement(): Promise<Announce> {
  loading ??= import('./planAnnouncement').then((m) => (announce = m.announcement));
  return loading;
}
if (typeof window !== 'undefined') {
  const idle = window.requestIdleCallback ?? ((run: () => void) => window.setTimeout(run, 200));
  idle(() => void loadAnnouncement().catch(() => undefined));
}

const snapshot = (s: ConfiguratorState): AnnouncedState => ({ config: s.config, selection: s.selection, past: s.history.past.length, future: s.history.future.length });

/**
 * A polite live region that tells screen-reader users what is selected on the plan and what
 * their last action changed (planAnnouncement.ts). It is always in the document, so assistive
 * technology is already watching it when the text changes; visually hidden, since sighted users
 * see the same on the plan.
 */
export function PlanAnnouncer({ store }: { store: ConfiguratorStore }) {
  const { t, format, language } = useI18n();
  const [message, setMessage] = useState('');
  const context = useRef<AnnounceContext>({ catalog: store.getState().catalog, t, format, language });
  useEffect(() => {
    context.current = { catalog: store.getState().catalog, t, format, language };
  }, [store, t, format, language]);
  useEffect(() => {
    let prev = snapshot(store.getState());
    let live = true;
    const unsubscribe = store.subscribe((state) => {
      const before = prev;
      const next = snapshot(state);
      prev = next;
      const speak = (announcement: Announce) => {
        const text = live ? announcement(before, next, context.current) : '';
        // The same sentence twice in a row (e.g. selecting one module again) is still spoken: a
        // changed text node is what live regions react to, so alternate a trailing no-break space.
        if (text) setMessage((old) => (old === text ? `${text}\u00a0` : text));
      };
      // In order: promise callbacks run in the order they were added.
      if (announce) speak(announce);
      else void loadAnnouncement().then(speak);
    });
    return () => {
      live = false;
      unsubscribe();
    };
  }, [store]);
  return (
    <div className="sr-only" role="status" aria-live="polite" aria-atomic="true" data-testid="plan-announcer">
      {message}
    </div>
  );
}
