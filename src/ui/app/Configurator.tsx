import { useEffect, useState } from 'react';
import { useStore } from 'zustand';
import { createConfiguration } from '../../core/model/configuration';
import { firstImpression } from '../viewer/firstImpression';
import { bakeHostOf } from '../viewer/bakeHost';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { Planner } from '../planner/Planner';
import type { FootprintSource } from '../planner/footprintSource';
import { RoomSetup } from './RoomSetup';
import type { UiStore } from '../../core/store/uiStore';
import './app.css';

export interface ConfiguratorProps {
  store: ConfiguratorStore;
  ui: UiStore;
  locale?: string;
  /** Loads the autosaved configuration (offered after a broken link). */
  onRestoreSaved: () => void;
  /** The share link of the current configuration, and the sentence saying what it leaves out (imported models), or null. */
  shareLink: () => { link: string; notice: string | null };
  footprints: FootprintSource;
}

/** The configurator's top-level component: room setup first, then the planner (configurator paper §3.2). */
export function Configurator({ store, ui, locale, onRestoreSaved, shareLink, footprints }: ConfiguratorProps) {
  const phase = useStore(ui, (s) => s.phase);
  const banner = useStore(ui, (s) => s.banner);
  const room = useStore(store, (s) => s.config.room);
  const catalog = useStore(store, (s) => s.catalog);
  const [shareNotice, setShareNotice] = useState<string | null>(null);

  // Once the plan shows, the 3D bake service starts in idle time and bakes every change in the
  // background, so the 3D view opens lit (docs/viewer.md, "Always ready: the bake service").
  useEffect(() => {
    if (phase !== 'planner') return;
    return bakeHostOf(store)?.startWhenIdle();
  }, [phase, store]);

  const startDemo = () => {
    const st = store.getState();
    st.load(firstImpression(catalog));
    const systems = store.getState().config.systems;
    if (systems.length > 0) store.getState().select({ kind: 'system', id: systems[systems.length - 1].id });
    ui.setState({ phase: 'planner' });
  };

  const share = () => {
    const { link, notice } = shareLink();
    // The clipboard needs a secure context and permission; the link is also shown as text.
    void navigator.clipboard?.writeText(link).catch(() => undefined);
    setShareNotice(notice);
    ui.setState({ shareLink: link });
    return notice ? 'Share link created without the imported models: see the side panel.' : 'Share link created: copy it from the side panel.';
  };

  return (
    <div className="app" lang={locale}>
      {banner && (
        <div className="banner" role="alert" data-testid="banner">
          <span className="banner-text">{banner.text}</span>
          {banner.canRestore && (
            <button type="button" className="btn" onClick={onRestoreSaved}>
              Open my saved configuration
            </button>
          )}
          <button type="button" className="btn" aria-label="Dismiss message" onClick={() => ui.setState({ banner: null })}>
            ✕
          </button>
        </div>
      )}
      {phase === 'setup' ? (
        <>
          <header className="app-header">
            <h1>luxbox</h1>
            <span className="room-label">Lighting configurator</span>
          </header>
          <RoomSetup
            initial={room}
            onSubmit={(r) => {
              store.getState().load(createConfiguration(r));
              ui.setState({ phase: 'planner', mode: '2d' });
            }}
            onDemo={startDemo}
          />
        </>
      ) : (
        <Planner
          store={store}
          ui={ui}
          locale={locale}
          onNewRoom={() => ui.setState({ phase: 'setup', optionsOpen: false, panelOpen: false })}
          onShare={share}
          shareNotice={shareNotice}
          footprints={footprints}
        />
      )}
    </div>
  );
}
