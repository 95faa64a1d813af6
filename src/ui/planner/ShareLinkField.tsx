import './registerPanelExtrasEnglish';
import { useState } from 'react';
import { useI18n } from '../i18n/useI18n';

export interface ShareLinkFieldProps {
  link: string;
  /** What the link leaves out (imported models), shown under it; null when complete. */
  notice: string | null;
}

type Outcome = 'copied' | 'copyFailed' | 'shared' | null;

/** Copies text: the async Clipboard API where the page may use it, else a selected hidden field and execCommand (older WebKit, http pages). */
async function copyText(text: string): Promise<boolean> {
  try {
    if (navigator.clipboard?.writeText) {
      await navigator.clipboard.writeText(text);
      return true;
    }
  } catch {
    // Denied (no secure context or permission): fall back below.
  }
  const field = document.createElement('textarea');
  field.value = text;
  field.setAttribute('readonly', '');
  field.style.position = 'fixed';
  field.style.opacity = '0';
  document.body.appendChild(field);
  field.select();
  try {
    return document.execCommand('copy');
  } catch {
    return false;
  } finally {
    field.remove();
  }
}

/**
 * The share link with one-tap actions (issue #27, "Share"): **Copy** (with a short confirmation,
 * or the reason to copy by hand), and **Share…** through the Web Share API where the browser has
 * it (phones and tablets: the system's share sheet). The link stays visible and selectable.
 */
export default function ShareLinkField({ link, notice }: ShareLinkFieldProps) {
  const { t } = useI18n();
  const [outcome, setOutcome] = useState<{ link: string; what: Outcome }>({ link, what: null });
  const shown = outcome.link === link ? outcome.what : null;
  const canShare = typeof navigator !== 'undefined' && typeof navigator.share === 'function';

  const copy = async () => setOutcome({ link, what: (await copyText(link)) ? 'copied' : 'copyFailed' });
  const share = async () => {
    try {
      await navigator.share({ title: t('sharing.shareTitle'), url: link });
      setOutcome({ link, what: 'shared' });
    } catch {
      // Cancelled by the user, or refused: nothing to say, the link is still here.
    }
  };

  return (
    <div className="field share-field">
      <label htmlFor="share-link">{t('planner.linkToConfiguration')}</label>
      <input id="share-link" readOnly value={link} onFocus={(e) => e.target.select()} data-testid="share-link" />
      <div className="setup-actions">
        <button type="button" className="btn" onClick={() => void copy()} data-testid="share-copy">
          {t('sharing.copyLink')}
        </button>
        {canShare && (
          <button type="button" className="btn" onClick={() => void share()} data-testid="share-native">
            {t('sharing.shareVia')}
          </button>
        )}
      </div>
      <p className="empty-note" role="status" data-testid="share-status">
        {shown === 'copied' ? t('sharing.linkCopied') : shown === 'copyFailed' ? t('sharing.linkCopyFailed') : shown === 'shared' ? t('sharing.linkShared') : ''}
      </p>
      {notice && (
        <p className="share-notice" role="note" data-testid="share-notice">
          ⚠ {notice}
        </p>
      )}
    </div>
  );
}
