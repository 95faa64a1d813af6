import { useCallback, useEffect, useState, useSyncExternalStore } from 'react';
import { useStore } from 'zustand';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { useI18n } from '../i18n/useI18n';
import { translateCoded } from '../i18n/translateCoded';
import { scenePlayerFor, type RecallResult, type ScenePlayer, type TransportStop } from './createScenePlayer';
import { SceneRow, type SceneAct } from './SceneRow';
import { useSceneKeys } from './useSceneKeys';
import './scenes.css';
import '../i18n/registerScenesEnglish';

/**
 * Light scenes in the side panel (docs/light-scenes.md), in 2D and 3D: GO / BACK like a lighting
 * console (next / previous in list order, each with its own fade), tap a scene to recall it, and
 * record, update, rename, reorder, delete and set the fade time. Space is GO, Shift+Space BACK.
 * Every change is a store action (undoable); the fade itself is the scene player's.
 */
export function ScenePanel({ store }: { store: ConfiguratorStore }) {
  const { t } = useI18n();
  const scenes = useStore(store, (s) => s.config.lightScenes) ?? [];
  const player = scenePlayerFor(store);
  const playback = useSyncExternalStore(player.subscribe, player.getState);
  const [renaming, setRenaming] = useState<{ id: string; name: string } | null>(null);
  const [note, setNote] = useState<string | null>(null);

  // A note (a refusal) goes after a few seconds, as the plan's status line does.
  useEffect(() => {
    if (!note) return;
    const id = window.setTimeout(() => setNote(null), 4000);
    return () => window.clearTimeout(id);
  }, [note]);

  const act: SceneAct = (action, params) => {
    const r = store.getState().dispatch(action, params);
    if (!r.ok) setNote(translateCoded(t, 'scenes', r));
    return r.ok;
  };
  const currentName = scenes.find((s) => s.id === playback.current)?.name ?? '';
  /** A transport stop worded for the user: GO at the last scene, BACK at the first, … */
  const stopText = useCallback((stop: TransportStop): string => (stop === 'lastScene' || stop === 'firstScene' ? t(`scenes.${stop}`, { name: currentName }) : t(`scenes.${stop}`)), [t, currentName]);
  const play = useCallback(
    (p: Promise<RecallResult>) => {
      void p.then((r) => {
        // GO at the last scene, BACK at the first: said, not silently ignored (a console stops at the end of its list).
        if (!r.ok) setNote(r.code ? stopText(r.code) : r.reason);
      });
    },
    [stopText],
  );
  useSceneKeys(player, play);
  const endRename = (commit: boolean) => {
    if (!renaming) return;
    if (!commit || act('renameScene', { sceneId: renaming.id, name: renaming.name })) setRenaming(null);
  };
  const fading = playback.fading;

  return (
    <section className="panel-section scene-panel" aria-labelledby="scenes-title" data-testid="scene-panel">
      <h2 id="scenes-title">{t('scenes.title')}</h2>
      <SceneTransport player={player} stopText={stopText} play={play} onStopped={setNote} />
      {fading && (
        <div className="scene-fade" role="progressbar" aria-label={t('scenes.fading')} aria-valuemin={0} aria-valuemax={100} aria-valuenow={Math.round(fading.t * 100)} data-testid="scene-fade">
          <div className="scene-fade-bar" style={{ width: `${Math.round(fading.t * 100)}%` }} />
        </div>
      )}
      {scenes.length === 0 ? (
        <p className="scene-empty">{t('scenes.empty')}</p>
      ) : (
        <ol className="scene-list">
          {scenes.map((s, i) => (
            <SceneRow
              key={s.id}
              scene={s}
              index={i}
              count={scenes.length}
              current={s.id === playback.current}
              renaming={renaming?.id === s.id ? renaming.name : null}
              act={act}
              onRecall={() => play(player.recall(s.id))}
              onRenameStart={() => setRenaming({ id: s.id, name: s.name })}
              onRenameChange={(name) => setRenaming({ id: s.id, name })}
              onRenameEnd={endRename}
            />
          ))}
        </ol>
      )}
      <SceneRecorder count={scenes.length} act={act} />
      {note && (
        <p className="scene-note" role="status" data-testid="scene-note">
          {note}
        </p>
      )}
    </section>
  );
}

interface SceneTransportProps {
  player: ScenePlayer;
  stopText: (stop: TransportStop) => string;
  play: (p: Promise<RecallResult>) => void;
  onStopped: (why: string) => void;
}

/** BACK and GO: a console's transport; at a stop the button stays focusable and a tap says why. */
function SceneTransport({ player, stopText, play, onStopped }: SceneTransportProps) {
  const { t } = useI18n();
  const next = player.next();
  const goStopCode = player.stop('go');
  const backStopCode = player.stop('back');
  const goStop = goStopCode && stopText(goStopCode);
  const backStop = backStopCode && stopText(backStopCode);
  return (
    <div className="scene-transport">
      {/* aria-disabled, not disabled: the button stays focusable and a tap says why (as every disabled control in luxbox). */}
      <button type="button" className="btn" aria-disabled={backStop !== null} title={backStop ?? undefined} onClick={() => (backStop ? onStopped(backStop) : play(player.back()))} data-testid="scene-back" aria-keyshortcuts="Shift+Space">
        {t('scenes.back')}
      </button>
      <button type="button" className="btn btn-primary scene-go" aria-disabled={goStop !== null} title={goStop ?? undefined} onClick={() => (goStop ? onStopped(goStop) : play(player.go()))} data-testid="scene-go" aria-keyshortcuts="Space">
        {next ? t('scenes.goTo', { name: next.name }) : t('scenes.go')}
      </button>
    </div>
  );
}

/** Records the present look as a new scene, under the typed name or "Scene n". */
function SceneRecorder({ count, act }: { count: number; act: SceneAct }) {
  const { t } = useI18n();
  const [name, setName] = useState('');
  const record = () => {
    const n = name.trim() || t('scenes.defaultName', { n: count + 1 });
    if (act('recordScene', { name: n })) setName('');
  };
  return (
    <div className="scene-record">
      <input
        value={name}
        placeholder={t('scenes.namePlaceholder')}
        aria-label={t('scenes.nameLabel')}
        onChange={(e) => setName(e.target.value)}
        onKeyDown={(e) => {
          if (e.key === 'Enter') record();
        }}
        data-testid="scene-name"
      />
      <button type="button" className="btn" onClick={record} data-testid="scene-record">
        {t('scenes.record')}
      </button>
    </div>
  );
}
