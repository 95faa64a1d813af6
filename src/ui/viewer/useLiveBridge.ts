import { useEffect, useRef, useState } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { levelsFromFrames, sameLevels, type LiveLevel } from '../../engines/view/liveLevels';
import { createBridgeClient, type BridgeState } from './createBridgeClient';
import { createFrameLatch, type FrameLatch } from './createFrameLatch';
import type { ViewerStatus } from './viewerStatus';

export interface LiveBridgeInput {
  on: boolean;
  port: number;
  config: Configuration;
  catalog: Catalog;
  onLevels(levels: ReadonlyMap<string, LiveLevel> | null): void;
  onStatus(live: ViewerStatus['live']): void;
}

/**
 * While `on`, a connection to the DMX bridge on 127.0.0.1:`port` whose frames are latched to one
 * per animation frame and turned into module levels (an overlay: the configuration is never
 * touched). Off, or on another port, the overlay is withdrawn. A configuration change (a patch
 * edit) re-reads the frames already held, so the view follows at once.
 */
export function useLiveBridge({ on, port, config, catalog, onLevels, onStatus }: LiveBridgeInput) {
  const [bridge, setBridge] = useState<BridgeState>({ kind: 'connecting' });
  const [levels, setLevels] = useState<ReadonlyMap<string, LiveLevel>>(new Map());
  const latch = useRef<FrameLatch | null>(null);
  // The latest props and configuration for callbacks that outlive a render (the latch, the socket).
  const latest = useRef({ config, onLevels, onStatus });
  useEffect(() => {
    latest.current = { config, onLevels, onStatus };
  });

  useEffect(() => {
    if (!on) return;
    let state: BridgeState = { kind: 'connecting' };
    let applied = 0;
    let last: ReadonlyMap<string, LiveLevel> | null = null;
    const report = () => latest.current.onStatus({ state: state.kind, received: l.counts.received, applied });
    const l = createFrameLatch((frames) => {
      const next = levelsFromFrames(latest.current.config, catalog, frames);
      if (!sameLevels(last, next)) {
        last = next;
        applied++;
        latest.current.onLevels(next);
        setLevels(next);
      }
      report();
    });
    latch.current = l;
    const client = createBridgeClient({
      url: `ws://127.0.0.1:${port}`,
      onState(s) {
        state = s;
        setBridge(s);
        report();
      },
      onFrame: (universe, channels) => l.put(universe, channels),
    });
    return () => {
      client.close();
      l.dispose();
      latch.current = null;
      // Off (or another port): the configuration's own dimming again.
      latest.current.onLevels(null);
      latest.current.onStatus(null);
      setLevels(new Map());
    };
  }, [on, port, catalog]);

  useEffect(() => {
    latch.current?.reapply();
  }, [config]);

  return { bridge, levels };
}
