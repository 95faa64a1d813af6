import { useMemo, useState } from 'react';
import { useStore } from 'zustand';
import { findModuleType } from '../../core/model/catalogSchema/catalogSchema';
import { isTunable, modulesInOrder } from '../../core/model/modules/dmxPatch';
import { type DmxPatch } from '../../core/model/configuration/configuration';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { LiveLevel } from '../../engines/view/liveLevels';
import { AutoPatchForm } from './AutoPatchForm';
import { BRIDGE_RETRY_S, type BridgeState } from './createBridgeClient';
import { PatchRow } from './PatchRow';
import { useLiveBridge } from './useLiveBridge';
import type { ViewerStatus } from './viewerStatus';
import { useI18n } from '../i18n/useI18n';
import type { Translate } from '../i18n/messageTypes';
import { localName } from '../i18n/localName';
import './registerView3dEnglish';

export const DEFAULT_BRIDGE_PORT = 9090;

export interface LiveControlProps {
  store: ConfiguratorStore;
  /** The overlay for the view (null: the configuration's own dimming again). */
  onLevels(levels: ReadonlyMap<string, LiveLevel> | null): void;
  /** For window.luxbox.view3d().live. */
  onStatus(live: ViewerStatus['live']): void;
}

function describe(t: Translate, state: BridgeState, url: string): string {
  switch (state.kind) {
    case 'connecting':
      return t('live.connecting', { url });
    case 'connected': {
      const s = state.status;
      if (!s) return t('live.connected', { url });
      const universes = s.universes.length > 0 ? t('live.universes', { count: s.universes.length, list: s.universes.join(', ') }) : t('live.noUniverse');
      const parts = [s.protocols.join(', ') || t('live.noProtocol'), universes, t('live.sources', { count: s.sources })];
      return t('live.connectedStatus', { details: parts.join(' · ') });
    }
    case 'no-bridge':
      return t('live.noBridge', { url, seconds: BRIDGE_RETRY_S });
    case 'lost':
      return t('live.bridgeLost', { seconds: BRIDGE_RETRY_S });
  }
}

/**
 * "Live control" in the 3D view's panel (docs/live-control.md): off by default;
 * on, it connects to the DMX bridge and relights the view from the console's
 * levels, once per animation frame at most, as an overlay that never touches
 * the configuration or its undo history. The patch it reads is the
 * configuration's (saved with it) and is edited here through undoable actions.
 */
export function LiveControl({ store, onLevels, onStatus }: LiveControlProps) {
  const { t, language } = useI18n();
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const [on, setOn] = useState(false);
  const [port, setPort] = useState(DEFAULT_BRIDGE_PORT);
  const { bridge, levels } = useLiveBridge({ on, port, config, catalog, onLevels, onStatus });
  const url = `ws://127.0.0.1:${port}`;

  const rows = useMemo(
    () =>
      modulesInOrder(config).map(({ module }) => {
        const type = findModuleType(catalog, module.type);
        return { id: module.id, typeName: localName(type, language), tunable: isTunable(type), patch: module.dmx };
      }),
    [config, catalog, language],
  );
  const dispatch = (name: string, params: unknown): string | null => {
    const r = store.getState().dispatch(name, params);
    return r.ok ? null : r.reason;
  };
  return (
    <div className="viewer3d-live" data-testid="live-control">
      <label className="viewer3d-field viewer3d-inline">
        <input type="checkbox" checked={on} onChange={(e) => setOn(e.target.checked)} data-testid="live-on" /> {t('live.title')}
      </label>
      {on && (
        <>
          <BridgePortField port={port} onPort={setPort} />
          <p className={`viewer3d-live-state viewer3d-live-${bridge.kind}`} role="status" data-testid="live-state" data-state={bridge.kind}>
            {describe(t, bridge, url)}
          </p>
          <p className="viewer3d-dim">{t('live.viewOnly')}</p>
          <AutoPatchForm onAutoPatch={(p) => dispatch('autoPatch', p)} onClear={() => dispatch('clearPatch', {})} canClear={rows.some((r) => r.patch)} />
          {rows.length > 0 ? (
            <ul className="viewer3d-patch" aria-label={t('live.patch')}>
              {rows.map((r) => (
                <PatchRow key={r.id} {...r} live={levels.get(r.id)} onPatch={(patch: DmxPatch | null) => dispatch('setModulePatch', { moduleId: r.id, patch })} />
              ))}
            </ul>
          ) : (
            <p className="viewer3d-dim">{t('live.nothingToPatch')}</p>
          )}
        </>
      )}
    </div>
  );
}

/** The bridge's port, typed; anything but a port number 1–65535 snaps back to the one in use. */
function BridgePortField({ port, onPort }: { port: number; onPort(port: number): void }) {
  const { t } = useI18n();
  const [portText, setPortText] = useState(String(port));
  const commitPort = () => {
    const p = Number(portText);
    if (Number.isInteger(p) && p >= 1 && p <= 65535) onPort(p);
    else setPortText(String(port));
  };
  return (
    <label className="viewer3d-field viewer3d-inline">
      {t('live.bridgePort')}
      <input
        type="number"
        min={1}
        max={65535}
        step={1}
        inputMode="numeric"
        value={portText}
        onChange={(e) => setPortText(e.target.value)}
        onBlur={commitPort}
        onKeyDown={(e) => e.key === 'Enter' && commitPort()}
        aria-label={t('live.bridgePortLabel')}
        data-testid="live-port"
      />
    </label>
  );
}
