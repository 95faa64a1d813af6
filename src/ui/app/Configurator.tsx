import { useEffect, useState } from 'react';
import { BrandMark } from '../shared/BrandMark';
import { useStore } from 'zustand';
import { createConfiguration } from '../../core/model/configuration/configuration';
import { firstImpression } from '../viewer/firstImpression';
import { bakeHostOf } from '../viewer/bakeHost';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { Planner } from '../planner/Planner';
import type { FirstRunOptions } from '../planner/FirstRunHint';
import type { FootprintSource } from '../planner/footprintSource';
import { RoomSetup, type RoomSetupProps } from './RoomSetup';
import type { UiStore } from '../../core/store/uiStore';
import { useI18n } from '../i18n/useI18n';
import { LanguageSwitch } from '../i18n/LanguageSwitch';
import { translateCoded } from '../i18n/translateCoded';
import { coreParams } from '../i18n/noticeText';
import type { Landmarks } from '../shared/landmarks';
import './app.css';

export interface ConfiguratorProps {
  store: ConfiguratorStore;
  ui: UiStore;
  /** Show the language switch in the top bar (the standalone app; an embedding shop chooses the locale). */
  languageSwitch?: boolean;
  /** Loads the autosaved configuration (offered after a broken link). */
  onRestoreSaved: () => void;
  /** The share link of the current configuration, and the names of the imported models it leaves out. */
  shareLink: () => { link: string; leftOut: readonly string[] };
  footprints: FootprintSource;
  /**
   * Which landmarks luxbox draws (docs/accessibility.md, "Landmarks"): 'page' when it is the whole
   * page (the standalone app: its header is the page's banner, the plan or room setup its one main),
   * 'region' when it is embedded (default): one region named "luxbox lighting configurator" around all of
   * it, so the host page keeps its own banner and main.
   */
  landmarks?: Landmarks;
  /** The empty plan's preset suggestions (docs/embedding.md, `firstRun`). */
  firstRun?: FirstRunOptions | false;
}

/** The configurator's top-level component: room setup first, then the planner (configurator paper §3.2). */
export function Configurator({ store, ui, languageSwitch = false, onRestoreSaved, shareLink, footprints, landmarks = 'region', firstRun }: ConfiguratorProps) {
  const { t, locale } = useI18n();
  const phase = useStore(ui, (s) => s.phase);
  const banner = useStore(ui, (s) => s.banner);
  const room = useStore(store, (s) => s.config.room);
  const catalog = useStore(store, (s) => s.catalog);
  const [leftOut, setLeftOut] = useState<readonly string[]>([]);
  const shareNotice = leftOut.length === 0 ? null : t('app.shareLeftOut', { count: leftOut.length, names: leftOut.map((n) => `'${n}'`).join(', ') });

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
    const { link, leftOut: names } = shareLink();
    // One tap shares (issue 27): where the browser has the Web Share API (phones, tablets) the
    // system's share sheet opens at once, inside this tap's user activation; elsewhere the link goes
    // to the clipboard. Either way the link is also shown, with Copy and Share… beside it.
    if (typeof navigator.share === 'function') void navigator.share({ url: link }).catch(() => undefined);
    // The clipboard needs a secure context and permission.
    else void navigator.clipboard?.writeText(link).catch(() => undefined);
    setLeftOut(names);
    ui.setState({ shareLink: link });
    return names.length > 0 ? t('app.shareCreatedWithoutModels') : t('app.shareCreated');
  };

  // Embedded: a named section is a region landmark, and a <header> inside it is no banner (HTML-AAM),
  // so nothing of luxbox competes with the host page's own banner and main.
  const Root = landmarks === 'page' ? 'div' : 'section';
  return (
    <Root className="app" lang={locale} aria-label={landmarks === 'page' ? undefined : t('app.regionLabel')}>
      {banner && <Banner ui={ui} onRestoreSaved={onRestoreSaved} />}
      {phase === 'setup' ? (
        <SetupPage
          ui={ui}
          languageSwitch={languageSwitch}
          landmarks={landmarks}
          initial={room}
          onSubmit={(r) => {
            store.getState().load(createConfiguration(r));
            ui.setState({ phase: 'planner', mode: '2d' });
          }}
          onDemo={startDemo}
        />
      ) : (
        <Planner
          store={store}
          ui={ui}
          languageSwitch={languageSwitch}
          onNewRoom={() => ui.setState({ phase: 'setup', optionsOpen: false, panelOpen: false })}
          onShare={share}
          shareNotice={shareNotice}
          footprints={footprints}
          landmarks={landmarks}
          firstRun={firstRun}
        />
      )}
    </Root>
  );
}

/** A notice across the top (a broken link, a refused file), with "open saved" where that helps, and dismiss. */
function Banner({ ui, onRestoreSaved }: { ui: UiStore; onRestoreSaved: () => void }) {
  const { t, language } = useI18n();
  const banner = useStore(ui, (s) => s.banner);
  if (!banner) return null;
  return (
    <div className="banner" role="alert" data-testid="banner">
      <span className="banner-text">{translateCoded(t, 'app', banner, coreParams(t, language))}</span>
      {banner.canRestore && (
        <button type="button" className="btn" onClick={onRestoreSaved}>
          {t('app.openSaved')}
        </button>
      )}
      <button type="button" className="btn" aria-label={t('common.dismissMessage')} onClick={() => ui.setState({ banner: null })}>
        ✕
      </button>
    </div>
  );
}

interface SetupPageProps {
  ui: UiStore;
  languageSwitch: boolean;
  landmarks: Landmarks;
  initial: RoomSetupProps['initial'];
  onSubmit: RoomSetupProps['onSubmit'];
  onDemo: () => void;
}

/** The first page: the brand, the tagline and the language switch over the room form. */
function SetupPage({ ui, languageSwitch, landmarks, initial, onSubmit, onDemo }: SetupPageProps) {
  const { t } = useI18n();
  return (
    <>
      <header className="app-header">
        <BrandMark ui={ui} />
        <span className="room-label">{t('app.tagline')}</span>
        <span className="spacer" />
        {languageSwitch && <LanguageSwitch />}
      </header>
      <RoomSetup initial={initial} onSubmit={onSubmit} onDemo={onDemo} landmarks={landmarks} />
    </>
  );
}
