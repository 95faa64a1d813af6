import { codePhotometryWarning } from '../../core/photometry/photometryCodes';
import { translateCoded } from '../i18n/translateCoded';
import { useI18n } from '../i18n/useI18n';
/** A photometric file and its warnings (photometryWarnings: one line each, without the file name). */
export interface PhotometryNote {
  /** The file as the catalog names it (a path such as `ies/x.ies`; its last part is shown). */
  file: string;
  warnings: readonly string[];
}

/** The file name shown for a catalog photometry path: its last part. */
export const photometryFileName = (path: string): string => path.slice(path.lastIndexOf('/') + 1);

/** A file name that may wrap after `_`, `-` and `.` in a narrow column (a phone, the 3D view's panel). */
function breakable(name: string): React.ReactNode[] {
  return name.split(/(?<=[_.-])/).flatMap((part, i) => (i === 0 ? [part] : [<wbr key={i} />, part]));
}

/**
 * Suspicious-but-readable photometric data (docs/photometry.md, "Warnings"), shown where the
 * file's light is shown: the module options and the 3D view. A small note, not an alert (the
 * light is still drawn, from the data as read); nothing at all when no file has a warning.
 * `collapsed`: one summary line ("⚠ Photometric data: 2 warnings") that opens to the text.
 */
export function PhotometryWarnings({ notes, testId = 'photometry-warnings', collapsed = false }: { notes: readonly PhotometryNote[]; testId?: string; collapsed?: boolean }) {
  const { t, language } = useI18n();
  // English shows the reader's own sentence (as the file report and `luxbox ies info` write it); other languages word its code.
  const say = (w: string) => (language === 'en' ? w : translateCoded(t, 'photometry', codePhotometryWarning(w)));
  const shown = notes.filter((n) => n.warnings.length > 0);
  if (shown.length === 0) return null;
  const body = shown.map((n) => (
    <div key={n.file} className="photometry-warnings-file">
      <p className="photometry-warnings-title">
        <span aria-hidden="true">⚠ </span>
        {breakable(photometryFileName(n.file))}
      </p>
      <ul>
        {n.warnings.map((w) => (
          <li key={w}>{say(w)}</li>
        ))}
      </ul>
    </div>
  ));
  if (!collapsed) {
    return (
      <div className="photometry-warnings" role="note" aria-label={t('shared.photometryWarnings')} data-testid={testId}>
        {body}
      </div>
    );
  }
  const count = shown.reduce((n, s) => n + s.warnings.length, 0);
  return (
    <div className="photometry-warnings" role="note" aria-label={t('shared.photometryWarnings')} data-testid={testId}>
      <details>
        <summary>
          <span aria-hidden="true">⚠ </span>
          {t('shared.photometryWarningCount', { count })}
        </summary>
        <div className="photometry-warnings-body">{body}</div>
      </details>
    </div>
  );
}
