import type { ReactNode } from 'react';
import type { ActionName, ActionParams } from '../../core/model/actions/actionDefinitions';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';

export interface GatedButtonProps<N extends ActionName> {
  gate: ActionGate;
  /** The model action the button runs, and its parameters. */
  action: N;
  params: ActionParams<N>;
  label: string;
  /**
   * For a choice among options (type, beam, colour temperature, …): the option in use shows
   * pressed and pressing it again does nothing, so it is never shown as refused.
   */
  current?: boolean;
  /** After the action ran (e.g. select what it added). */
  onRan?: () => void;
  children?: ReactNode;
  testId?: string;
}

/**
 * The gate pattern in one place: an ActionButton enabled exactly when the model's isEnabled
 * accepts `action(params)`, with the model's reason as its disabled title and tap message, and
 * the model's remedy (core remedyFor) offered in the planner's tip when there is one.
 */
export function GatedButton<N extends ActionName>({ gate, action, params, label, current, onRan, children, testId }: GatedButtonProps<N>) {
  return (
    <ActionButton
      label={label}
      pressed={current}
      disabledReason={current ? null : gate.reason(action, params)}
      onPress={() => {
        if (current) return;
        gate.run(action, params);
        onRan?.();
      }}
      onDisabledPress={gate.explain}
      action={{ name: action, params }}
      testId={testId}
    >
      {children}
    </ActionButton>
  );
}
