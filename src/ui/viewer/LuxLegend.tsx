import { legendPosition, turbo } from '../../engines/view/falseColorScale';
import { useI18n } from '../i18n/useI18n';
import './registerView3dEnglish';

/**
 * The false-colour legend: each level (highest first) with the colour the shader gives it; with
 * `percentOf` (the daylight-factor view: the outdoor illuminance, lux) each level as a DF in %.
 */
export function LuxLegend({ levels, percentOf }: { levels: readonly number[]; percentOf?: number }) {
  const { t, format } = useI18n();
  return (
    <div className="viewer3d-legend" aria-label={t(percentOf ? 'view3d.dfLegend' : 'view3d.legend')} data-testid="view3d-legend">
      {[...levels].reverse().map((v) => {
        const [r, g, b] = turbo(legendPosition(v, levels));
        return (
          <div key={v} className="viewer3d-legend-row">
            <span className="viewer3d-swatch" style={{ background: `rgb(${r * 255}, ${g * 255}, ${b * 255})` }} />
            {percentOf ? `${format.number((100 * v) / percentOf)} %` : `${format.number(v)} lx`}
          </div>
        );
      })}
    </div>
  );
}
