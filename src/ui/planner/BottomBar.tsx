import { CommandButton } from './CommandButton';
import type { PlannerController } from './PlannerController';
import { useI18n } from '../i18n/useI18n';

/**
 * The configurator paper's bottom navigation (figure 6): delete, select, options, rotate, plus undo/redo and
 * the 2D/3D toggle, each a command of plannerCommands.ts (the keyboard runs the same ones).
 * Labels are visible text, not hover-only icons.
 */
export function BottomBar({ controller, mode }: { controller: PlannerController; mode: '2d' | '3d' }) {
  const { t } = useI18n();
  const tool = (id: string, testId: string, icon: string, text: string) => (
    <CommandButton controller={controller} id={id} testId={testId}>
      <span className="icon" aria-hidden>
        {icon}
      </span>
      {text}
    </CommandButton>
  );
  return (
    <nav className="bottom-bar" aria-label={t('planner.tools')}>
      {tool('delete', 'tool-delete', '✕', t('planner.toolDelete'))}
      {tool('select-next', 'tool-select', '⬚', t('planner.toolSelect'))}
      {tool('options', 'tool-options', '⚙', t('planner.toolOptions'))}
      {tool('rotate', 'tool-rotate', '⟲', t('planner.toolRotate'))}
      {tool('undo', 'tool-undo', '↶', t('planner.toolUndo'))}
      {tool('redo', 'tool-redo', '↷', t('planner.toolRedo'))}
      <span className="sep" />
      {tool('toggle-3d', 'tool-3d', mode === '2d' ? '3D' : '2D', mode === '2d' ? t('planner.toolView3d') : t('planner.toolView2d'))}
    </nav>
  );
}
