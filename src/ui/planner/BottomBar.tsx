import { checkAction } from '../../core/model/actionDefinitions';
import type { Configuration } from '../../core/model/configuration';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { UiStore } from '../../core/store/uiStore';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';
import { deleteTarget } from './deleteTarget';
import type { SelectionPath } from './selection';

export interface BottomBarProps {
  store: ConfiguratorStore;
  ui: UiStore;
  config: Configuration;
  path: SelectionPath;
  gate: ActionGate;
  canUndo: boolean;
  canRedo: boolean;
  mode: '2d' | '3d';
}

/** Degrees the bottom bar's rotate button (and the R key) turn a system: a quarter turn, counterclockwise. */
export const ROTATE_STEP = 90;

/**
 * The configurator paper's bottom navigation (figure 6): delete, select, options, rotate, plus undo/redo and
 * the 2D/3D toggle. Labels are visible text, not hover-only icons.
 */
export function BottomBar({ store, ui, config, path, gate, canUndo, canRedo, mode }: BottomBarProps) {
  const del = deleteTarget(path);
  const delReason = 'reason' in del ? del.reason : (() => {
    const e = checkAction(config, del.name, del.params, store.getState().catalog);
    return e === true ? null : e.reason;
  })();
  const systems = config.systems;
  const rotateReason = path.systemId ? gate.reason('rotateSystem', { systemId: path.systemId, by: ROTATE_STEP }) : 'select a system first';

  const selectNext = () => {
    const i = systems.findIndex((s) => s.id === path.systemId);
    const next = systems[(i + 1) % systems.length];
    store.getState().select({ kind: 'system', id: next.id });
  };

  return (
    <nav className="bottom-bar" aria-label="Tools">
      <ActionButton label="Delete" disabledReason={delReason} onPress={() => !('reason' in del) && gate.run(del.name, del.params as never)} onDisabledPress={gate.explain} testId="tool-delete">
        <span className="icon" aria-hidden>✕</span>
        Delete
      </ActionButton>
      <ActionButton label="Select next system" disabledReason={systems.length === 0 ? 'place a preset first' : null} onPress={selectNext} onDisabledPress={gate.explain} testId="tool-select">
        <span className="icon" aria-hidden>⬚</span>
        Select
      </ActionButton>
      <ActionButton
        label="Options"
        pressed={ui.getState().optionsOpen}
        disabledReason={null}
        onPress={() => ui.setState((s) => ({ optionsOpen: !s.optionsOpen, panelOpen: !s.optionsOpen }))}
        testId="tool-options"
      >
        <span className="icon" aria-hidden>⚙</span>
        Options
      </ActionButton>
      <ActionButton label="Rotate" disabledReason={rotateReason} onPress={() => path.systemId && gate.run('rotateSystem', { systemId: path.systemId, by: ROTATE_STEP })} onDisabledPress={gate.explain} testId="tool-rotate">
        <span className="icon" aria-hidden>⟲</span>
        Rotate
      </ActionButton>
      <ActionButton label="Undo" disabledReason={canUndo ? null : 'nothing to undo'} onPress={() => store.getState().undo()} onDisabledPress={gate.explain} testId="tool-undo">
        <span className="icon" aria-hidden>↶</span>
        Undo
      </ActionButton>
      <ActionButton label="Redo" disabledReason={canRedo ? null : 'nothing to redo'} onPress={() => store.getState().redo()} onDisabledPress={gate.explain} testId="tool-redo">
        <span className="icon" aria-hidden>↷</span>
        Redo
      </ActionButton>
      <span className="sep" />
      <ActionButton label={mode === '2d' ? 'Show 3D view' : 'Show 2D plan'} pressed={mode === '3d'} disabledReason={null} onPress={() => ui.setState({ mode: mode === '2d' ? '3d' : '2d' })} testId="tool-3d">
        <span className="icon" aria-hidden>{mode === '2d' ? '3D' : '2D'}</span>
        {mode === '2d' ? 'View 3D' : 'View 2D'}
      </ActionButton>
    </nav>
  );
}
