import { useCallback, useEffect, useState, useSyncExternalStore } from 'react';
import { useStore } from 'zustand';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { useI18n } from '../i18n/useI18n';
import { decimalFieldFormat, parseDecimal } from '../i18n/decimalInput';
import { translateCoded } from '../i18n/translateCoded';
import { scenePlayerFor, type RecallResult, type TransportStop } from './createScenePlayer';
import { useSceneKeys } from './useSceneKeys';
import './scenes.css';
import '../i18n/registerScenesEnglish';

/**
 * Focuses the rename field when it appears. Not `autoFocus`: React focuses such an element on mount,
 * but preact (the browser build, docs/architecture.md) only sets the attribute, which browsers
 * honour once per page. A module-level callback, so it runs on mount only, not on every keystroke.
 */
const focusOnMount = (input: HTMLInputElement | null) => input?.focus();

/**
 * Light scenes in the side panel (docs/light-scenes.md), in 2D and 3D: GO / BACK like a lighting
 * console (next / previous in list order, each with its own fade), tap a scene to recall it, and
 * record, update, rename, reorder, delete and set the fade time. Space is GO, Shift+Space BACK.
 * Every change is a store action (undoable); the fade itself is the scene player's.
 */
export function ScenePanel({ store }: { store: ConfiguratorStore }) {
  const { t, format, locale } = useI18n();
  const fadeShown = (seconds: number) => format.number(seconds, decimalFieldFormat({ max: 2 }));
  const scenes = useStore(store, (s) => s.config.lightScenes) ?? [];
  const player = scenePlayerFor(store);
  const playback = useSyncExternalStore(player.subscribe, player.getState);
  const [name, setName] = useState('');
  const [renaming, setRenaming] = useState<{ id: string; name: string } | null>(null);
  const [note, setNote] = useState<string | null>(null);

  // A note (a refusal) goes after a few seconds, as the plan's status line does.
  useEffect(() => {
    if (!note) return;
    const id = window.setTimeout(() => setNote(null), 4000);
    return () => window.clearTimeout(id);
  }, [note]);

  const act = (action: string, params: unknown): boolean => {
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
  const record = () => {
    const n = name.trim() || t('scenes.defaultName', { n: scenes.length + 1 });
    if (act('recordScene', { name: n })) setName('');
  };
  const commitRename = () => {
    if (renaming && act('renameScene', { sceneId: renaming.id, name: renaming.name })) setRenaming(null);
  };
  const next = player.next();
  const goStopCode = player.stop('go');
  const backStopCode = player.stop('back');
  const goStop = goStopCode && stopText(goStopCode);
  const backStop = backStopCode && stopText(backStopCode);
  const fading = playback.fading;

  return (
    <section className="panel-section scene-panel" aria-labelledby="scenes-title" data-testid="scene-panel">
      <h2 id="scenes-title">{t('scenes.title')}</h2>
      <div className="scene-transport">
        {/* aria-disabled, not disabled: the button stays focusable and a tap says why (as every disabled control in luxbox). */}
        <button type="button" className="btn" aria-disabled={backStop !== null} title={backStop ?? undefined} onClick={() => (backStop ? setNote(backStop) : play(player.back()))} data-testid="scene-back" aria-keyshortcuts="Shift+Space">
          {t('scenes.back')}
        </button>
        <button type="button" className="btn btn-primary scene-go" aria-disabled={goStop !== null} title={goStop ?? undefined} onClick={() => (goStop ? setNote(goStop) : play(player.go()))} data-testid="scene-go" aria-keyshortcuts="Space">
          {next ? t('scenes.goTo', { name: next.name }) : t('scenes.go')}
        </button>
      </div>
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
            <li key={s.id} className={s.id === playback.current ? 'current' : undefined} data-testid="scene-row" data-scene-id={s.id} aria-current={s.id === playback.current || undefined}>
              {renaming?.id === s.id ? (
                <input
                  className="scene-name-input"
                  value={renaming.name}
                  ref={focusOnMount}
                  aria-label={t('scenes.nameLabel')}
                  onChange={(e) => setRenaming({ id: s.id, name: e.target.value })}
                  onKeyDown={(e) => {
                    if (e.key === 'Enter') commitRename();
                    if (e.key === 'Escape') setRenaming(null);
                  }}
                  onBlur={commitRename}
                  data-testid="scene-rename-input"
                />
              ) : (
                <button type="button" className="btn scene-recall" onClick={() => play(player.recall(s.id))} data-testid="scene-recall" title={t('scenes.recallHint', { name: s.name, seconds: format.number(s.fade) })}>
                  {s.name}
                </button>
              )}
              <label className="scene-fade-field">
                {/* Text with the locale's decimal mark ("1,5" in German), not type=number, which shows the browser's (docs/i18n.md, "Decimal input"). */}
                <input
                  inputMode="decimal"
                  autoComplete="off"
                  defaultValue={fadeShown(s.fade)}
                  key={`${s.id}-${s.fade}-${locale}`}
                  aria-label={t('scenes.fadeLabel', { name: s.name })}
                  onBlur={(e) => {
                    const v = parseDecimal(e.target.value);
                    if (v === s.fade) e.target.value = fadeShown(s.fade);
                    else if (!Number.isFinite(v) || !act('setSceneFade', { sceneId: s.id, fade: v })) e.target.value = fadeShown(s.fade);
                  }}
                  onKeyDown={(e) => {
                    if (e.key === 'Enter') (e.target as HTMLInputElement).blur();
                  }}
                  data-testid="scene-fade-input"
                />
                {t('scenes.seconds')}
              </label>
              <span className="scene-tools">
                <button type="button" className="btn" onClick={() => act('updateScene', { sceneId: s.id })} title={t('scenes.updateHint')} aria-label={t('scenes.updateLabel', { name: s.name })} data-testid="scene-update">
                  {t('scenes.update')}
                </button>
                <button type="button" className="btn" onClick={() => setRenaming({ id: s.id, name: s.name })} aria-label={t('scenes.renameLabel', { name: s.name })} data-testid="scene-rename">
                  {t('scenes.rename')}
                </button>
                <button type="button" className="btn" disabled={i === 0} onClick={() => act('reorderScene', { sceneId: s.id, index: i - 1 })} aria-label={t('scenes.moveUp', { name: s.name })}>
                  ↑
                </button>
                <button type="button" className="btn" disabled={i === scenes.length - 1} onClick={() => act('reorderScene', { sceneId: s.id, index: i + 1 })} aria-label={t('scenes.moveDown', { name: s.name })}>
                  ↓
                </button>
                <button type="button" className="btn" onClick={() => act('deleteScene', { sceneId: s.id })} aria-label={t('scenes.deleteLabel', { name: s.name })} data-testid="scene-delete">
                  ✕
                </button>
              </span>
            </li>
          ))}
        </ol>
      )}
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
      {note && (
        <p className="scene-note" role="status" data-testid="scene-note">
          {note}
        </p>
      )}
    </section>
  );
}
