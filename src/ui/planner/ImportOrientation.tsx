import './registerPanelExtrasEnglish';
import type { OrientationSummary } from '../../core/mesh/orientMesh';
import { useI18n } from '../i18n/useI18n';

/**
 * What orienting the model did (docs/furniture.md, "Which side of a face is lit"): closed parts
 * turned outward, open surfaces lit on both sides or from their front only, or that every part is
 * closed and faces outward; parts with no clear inside as a warning. Loaded with the import
 * preview (a lazy chunk: nothing of it is in the first screen).
 */
export default function ImportOrientation({ orientation: o }: { orientation: OrientationSummary }) {
  const { t } = useI18n();
  const lines: string[] = [];
  if (o.turnedOutward > 0) lines.push(t('modelImport.orientTurned', { count: o.turnedOutward }));
  if (o.twoSided > 0) lines.push(t('modelImport.orientTwoSided', { count: o.twoSided }));
  if (o.oneSided > 0) lines.push(t('modelImport.orientOneSided', { count: o.oneSided }));
  if (lines.length === 0 && o.undecided === 0) lines.push(t('modelImport.orientClosed'));
  return (
    <>
      {lines.length > 0 && (
        <p className="preset-detail" data-testid="import-orientation">
          {lines.join(' · ')}
        </p>
      )}
      {o.undecided > 0 && (
        <p className="import-warnings" role="note" data-testid="import-undecided">
          ⚠ {t('modelImport.orientUndecided', { count: o.undecided })}
        </p>
      )}
    </>
  );
}
