import type { LightScene } from '../../core/model/configuration/configuration';
import { useI18n } from '../i18n/useI18n';
import { decimalFieldFormat, parseDecimal } from '../i18n/decimalInput';

/** Runs a store action by name; false (with the refusal shown by the panel) when the model refused it. */
export type SceneAct = (action: string, params: unknown) => boolean;

/**
 * Focuses the rename field when it appears. Not `autoFocus`: React focuses such an element on mount,
 * but preact (the browser build, docs/architecture.md) only sets the attribute, which browsers
 * honour once per page. A module-level callback, so it runs on mount only, not on every keystroke.
 */
const focusOnMount = (input: HTMLInputElement | null) => input?.focus();

export interface SceneRowProps {
  scene: LightScene;
  index: number;
  count: number;
  current: boolean;
  renaming: string | null;
  act: SceneAct;
  onRecall: () => void;
  onRenameStart: () => void;
  onRenameChange: (name: string) => void;
  onRenameEnd: (commit: boolean) => void;
}

/** One scene of the list: recall (or its rename field), its fade time and its tools. */
export function SceneRow({ scene, index, count, current, renaming, act, onRecall, onRenameStart, onRenameChange, onRenameEnd }: SceneRowProps) {
  const { t, format } = useI18n();
  return (
    <li className={current ? 'current' : undefined} data-testid="scene-row" data-scene-id={scene.id} aria-current={current || undefined}>
      {renaming !== null ? (
        <input
          className="scene-name-input"
          value={renaming}
          ref={focusOnMount}
          aria-label={t('scenes.nameLabel')}
          onChange={(e) => onRenameChange(e.target.value)}
          onKeyDown={(e) => {
            if (e.key === 'Enter') onRenameEnd(true);
            if (e.key === 'Escape') onRenameEnd(false);
          }}
          onBlur={() => onRenameEnd(true)}
          data-testid="scene-rename-input"
        />
      ) : (
        <button type="button" className="btn scene-recall" onClick={onRecall} data-testid="scene-recall" title={t('scenes.recallHint', { name: scene.name, seconds: format.number(scene.fade) })}>
          {scene.name}
        </button>
      )}
      <SceneFadeField scene={scene} act={act} />
      <SceneTools scene={scene} index={index} count={count} act={act} onRenameStart={onRenameStart} />
    </li>
  );
}

/** The scene's fade time in seconds, typed with the locale's decimal mark; a refused value snaps back. */
function SceneFadeField({ scene, act }: { scene: LightScene; act: SceneAct }) {
  const { t, format, locale } = useI18n();
  const fadeShown = (seconds: number) => format.number(seconds, decimalFieldFormat({ max: 2 }));
  return (
    <label className="scene-fade-field">
      {/* Text with the locale's decimal mark ("1,5" in German), not type=number, which shows the browser's (docs/i18n.md, "Decimal input"). */}
      <input
        inputMode="decimal"
        autoComplete="off"
        defaultValue={fadeShown(scene.fade)}
        key={`${scene.id}-${scene.fade}-${locale}`}
        aria-label={t('scenes.fadeLabel', { name: scene.name })}
        onBlur={(e) => {
          const v = parseDecimal(e.target.value);
          if (v === scene.fade) e.target.value = fadeShown(scene.fade);
          else if (!Number.isFinite(v) || !act('setSceneFade', { sceneId: scene.id, fade: v })) e.target.value = fadeShown(scene.fade);
        }}
        onKeyDown={(e) => {
          if (e.key === 'Enter') (e.target as HTMLInputElement).blur();
        }}
        data-testid="scene-fade-input"
      />
      {t('scenes.seconds')}
    </label>
  );
}

/** Update, rename, move up/down and delete: each a store action (undoable). */
function SceneTools({ scene, index, count, act, onRenameStart }: { scene: LightScene; index: number; count: number; act: SceneAct; onRenameStart: () => void }) {
  const { t } = useI18n();
  const sceneId = scene.id;
  return (
    <span className="scene-tools">
      <button type="button" className="btn" onClick={() => act('updateScene', { sceneId })} title={t('scenes.updateHint')} aria-label={t('scenes.updateLabel', { name: scene.name })} data-testid="scene-update">
        {t('scenes.update')}
      </button>
      <button type="button" className="btn" onClick={onRenameStart} aria-label={t('scenes.renameLabel', { name: scene.name })} data-testid="scene-rename">
        {t('scenes.rename')}
      </button>
      <button type="button" className="btn" disabled={index === 0} onClick={() => act('reorderScene', { sceneId, index: index - 1 })} aria-label={t('scenes.moveUp', { name: scene.name })}>
        ↑
      </button>
      <button type="button" className="btn" disabled={index === count - 1} onClick={() => act('reorderScene', { sceneId, index: index + 1 })} aria-label={t('scenes.moveDown', { name: scene.name })}>
        ↓
      </button>
      <button type="button" className="btn" onClick={() => act('deleteScene', { sceneId })} aria-label={t('scenes.deleteLabel', { name: scene.name })} data-testid="scene-delete">
        ✕
      </button>
    </span>
  );
}
