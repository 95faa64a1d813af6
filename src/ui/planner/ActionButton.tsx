import type { CSSProperties, ReactNode } from 'react';
import { useI18n } from '../i18n/useI18n';
import { useDisabledTip } from './disabledTip';
import type { RemedyOffer } from './actionGate';

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
  /** What would make it enabled (a refused "+": a larger driver), offered in the tip at the control; asked only when the disabled button is pressed. */
  remedy?: () => RemedyOffer | null;
}

/**
 * A button whose disabled state comes only from the model's `isEnabled`. It stays focusable
 * and clickable when disabled (aria-disabled, not the `disabled` attribute) so the reason is
 * both a tooltip (title) and, on a tap, a tip anchored to the button (and the status line): no
 * hover-only information.
 */
export function ActionButton(props: ActionButtonProps) {
  const { label, disabledReason, onPress, onDisabledPress, children, className, style, pressed, testId, remedy } = props;
  const { t } = useI18n();
  const tip = useDisabledTip();
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
          onDisabledPress?.(disabledReason);
          // Where the finger is: the reason (and its remedy) in a tip at this control (docs/planner.md, "Reasons at the control").
          tip?.show(disabledReason, e.currentTarget, remedy?.() ?? null);
        } else onPress();
      }}
    >
      {children ?? label}
    </button>
  );
}
