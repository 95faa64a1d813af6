import type { CSSProperties, ReactNode } from 'react';
import { useI18n } from '../i18n/useI18n';
import { REFUSED_EVENT, type RefusedDetail } from './disabledTip';
import type { ActionName } from '../../core/model/actions/actionDefinitions';

export interface ActionButtonProps {
  /** Accessible name (also the visible label when no icon is given). */
  label: string;
  /** null when the action may run; otherwise the model's reason it may not. */
  disabledReason: string | null;
  onPress: () => void;
  /** Called instead of onPress when disabled, so touch users (no hover) can learn why. */
  onDisabledPress?: (reason: string) => void;
  children?: ReactNode;
  className?: string;
  style?: CSSProperties;
  pressed?: boolean;
  testId?: string;
  /** The model action it runs: a planner's tip at the refused control offers what would make it enabled (a refused "+": a larger driver). */
  action?: { name: ActionName; params: unknown };
}

/**
 * A button whose disabled state comes only from the model's `isEnabled`. It stays focusable
 * and clickable when disabled (aria-disabled, not the `disabled` attribute) so the reason is
 * both a tooltip (title) and, on a tap, a tip anchored to the button (and the status line): no
 * hover-only information.
 */
export function ActionButton(props: ActionButtonProps) {
  const { label, disabledReason, onPress, onDisabledPress, children, className, style, pressed, testId, action } = props;
  const { t } = useI18n();
  const disabled = disabledReason !== null;
  return (
    <button
      type="button"
      className={`action-button${className ? ` ${className}` : ''}`}
      style={style}
      aria-label={label}
      aria-disabled={disabled || undefined}
      aria-pressed={pressed}
      title={disabled ? t('common.labelWithReason', { label, reason: disabledReason }) : label}
      data-testid={testId}
      onClick={(e) => {
        e.stopPropagation();
        if (disabled) {
          // Where the finger is: a planner shows the reason (and its remedy) in a tip at this control and
          // takes the event (docs/planner.md, "Reasons at the control"); elsewhere the status line explains.
          const detail: RefusedDetail = { reason: disabledReason, action };
          if (e.currentTarget.dispatchEvent(new CustomEvent(REFUSED_EVENT, { bubbles: true, cancelable: true, detail }))) onDisabledPress?.(disabledReason);
        } else onPress();
      }}
    >
      {children ?? label}
    </button>
  );
}
