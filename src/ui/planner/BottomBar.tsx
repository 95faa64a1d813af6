import { CommandButton } from './CommandButton';
import type { PlannerController } from './PlannerController';

/**
 * The configurator paper's bottom navigation (figure 6): delete, select, options, rotate, plus undo/redo and
 * the 2D/3D toggle, each a command of plannerCommands.ts (the keyboard runs the same ones).
 * Labels are visible text, not hover-only icons.
 */
export function BottomBar({ controller, mode }: { controller: PlannerController; mode: '2d' | '3d' }) {
  const tool = (id: string, testId: string, icon: string, text: string) => (
    <CommandButton controller={controller} id={id} testId={testId}>
      <span className="icon" aria-hidden>
        {icon}
      </span>
      {text}
    </CommandButton>
  );
  return (
    <nav className="bottom-bar" aria-label="Tools">
      {tool('delete', 'tool-delete', '✕', 'Delete')}
      {tool('select-next', 'tool-select', '⬚', 'Select')}
      {tool('options', 'tool-options', '⚙', 'Options')}
      {tool('rotate', 'tool-rotate', '⟲', 'Rotate')}
      {tool('undo', 'tool-undo', '↶', 'Undo')}
      {tool('redo', 'tool-redo', '↷', 'Redo')}
      <span className="sep" />
      {tool('toggle-3d', 'tool-3d', mode === '2d' ? '3D' : '2D', mode === '2d' ? 'View 3D' : 'View 2D')}
    </nav>
  );
}
