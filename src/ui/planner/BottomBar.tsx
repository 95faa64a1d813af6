import { useRef } from 'react';
import { CommandButton } from './CommandButton';
import type { PlannerController } from './PlannerController';
import { useI18n } from '../i18n/useI18n';
import { useFitCompact } from './useFitCompact';

/**
 * The configurator paper's bottom navigation (figure 6): delete, select, options, rotate, plus undo/redo and
 * the 2D/3D toggle, each a command of plannerCommands.ts (the keyboard runs the same ones).
 * Labels are visible text, not hover-only icons, wherever they fit; on a phone where they do not
 * (measured by useFitCompact: German, French, Italian at 360 px), the bar shows its icons alone,
 * each button keeping its full label as accessible name and title.
 */
export function BottomBar({ controller, mode }: { controller: PlannerController; mode: '2d' | '3d' }) {
  const { t } = useI18n();
  const ref = useRef<HTMLElement>(null);
  useFitCompact(ref);
  const tool = (id: string, testId: string, icon: string, text: string) => (
    <CommandButton controller={controller} id={id} testId={testId}>
      <span className="icon" aria-hidden>
        {icon}
      </span>
      <span className="tool-text">{text}</span>
    </CommandButton>
  );
  return (
    <nav ref={ref} className="bottom-bar" aria-label={t('planner.tools')}>
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
