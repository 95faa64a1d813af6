import { useCallback, useSyncExternalStore, type ReactNode } from 'react';
import { ActionButton } from './ActionButton';
import type { PlannerController } from './PlannerController';
import { commandLabel, plannerCommand } from './plannerCommands';

interface CommandButtonState {
  label: string;
  reason: string | null;
  pressed: boolean | undefined;
}

/** A command's label, enablement and pressed state, kept up to date with both stores it may read. */
function useCommandState(controller: PlannerController, id: string): CommandButtonState {
  const { store, ui } = controller;
  const subscribe = useCallback(
    (onChange: () => void) => {
      const offStore = store.subscribe(onChange);
      const offUi = ui.subscribe(onChange);
      return () => {
        offStore();
        offUi();
      };
    },
    [store, ui],
  );
  // A string snapshot: equal states compare equal, so unrelated store changes do not re-render.
  const snapshot = useCallback(() => {
    const command = plannerCommand(id);
    return JSON.stringify([commandLabel(command, controller), command.disabledReason(controller), command.pressed?.(controller)]);
  }, [controller, id]);
  const [label, reason, pressed] = JSON.parse(useSyncExternalStore(subscribe, snapshot, snapshot)) as [string, string | null, boolean | null];
  return { label, reason, pressed: pressed ?? undefined };
}

/**
 * A button for a command of the planner's table (bottom bar, zoom buttons): the same
 * enablement and action as its key. `children` is the visible face; the label is its name.
 */
export function CommandButton({ controller, id, testId, children }: { controller: PlannerController; id: string; testId: string; children?: ReactNode }) {
  const { label, reason, pressed } = useCommandState(controller, id);
  return (
    <ActionButton label={label} pressed={pressed} disabledReason={reason} onPress={() => controller.command(id)} onDisabledPress={controller.explain} testId={testId}>
      {children}
    </ActionButton>
  );
}
