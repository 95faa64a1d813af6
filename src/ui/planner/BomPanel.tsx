import type { BillOfMaterials } from '../../core/model/power/billOfMaterials';
import type { InstallationNeeds } from '../../core/model/power/installationNeeds';
import { formatWatts } from '../../core/model/power/feedLoads';
import { useI18n } from '../i18n/useI18n';
import { formatMoney } from './formatMoney';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { bomLineName } from '../i18n/bomLineName';

export interface BomPanelProps {
  bom: BillOfMaterials;
  /** The catalog the lines come from: their names are shown in the UI language (bomLineName); without it, as the BOM has them. */
  catalog?: Catalog;
  /** Formats prices for this locale instead of the UI's (a panel rendered on its own, in a test); the texts stay the UI language's. */
  locale?: string;
  /** The installer's summary before the cart hand-off (feeds, ceiling fixings, load); omitted: not shown. */
  needs?: InstallationNeeds;
}

/**
 * Live bill of materials with prices (the configurator paper's planned live price): article, count ×
 * unit price, total. Three columns, so the table fits the side panel at every width (issue 27): in the
 * 340 px phone drawer four columns pushed the totals out of view in German.
 */
export function BomPanel({ bom, needs, locale, catalog }: BomPanelProps) {
  const { t, format, language } = useI18n();
  const money = (x: number) => (locale ? formatMoney(x, bom.currency, locale) : format.money(x, bom.currency));
  return (
    <section className="panel-section" aria-labelledby="bom-title" data-testid="bom">
      <h2 id="bom-title">{t('planner.bomTitle')}</h2>
      {bom.lines.length === 0 ? (
        <p className="empty-note">{t('planner.bomEmpty')}</p>
      ) : (
        <table className="bom-table">
          <thead>
            <tr>
              <th scope="col">{t('planner.bomArticle')}</th>
              <th scope="col" className="num">
                {t('planner.bomQuantityPrice')}
              </th>
              <th scope="col" className="num">
                {t('planner.bomLineTotal')}
              </th>
            </tr>
          </thead>
          <tbody>
            {bom.lines.map((l) => (
              <tr key={l.article}>
                <td>
                  <div>{catalog ? bomLineName(l, catalog, language, t, format) : l.name}</div>
                  <div className="preset-detail">{l.article}</div>
                </td>
                {/* May break after the ×, never inside a number or price (no-break space before it). */}
                <td className="num qty-price">
                  {format.number(l.count)}
                  {'\u00a0× '}
                  {money(l.unitPrice)}
                </td>
                <td className="num">{money(l.total)}</td>
              </tr>
            ))}
          </tbody>
          <tfoot>
            <tr>
              <td colSpan={2}>{t('planner.bomTotal', { currency: bom.currency })}</td>
              <td className="num" data-testid="bom-total">
                {money(bom.total)}
              </td>
            </tr>
          </tfoot>
        </table>
      )}
      {bom.lines.length > 0 && <p className="preset-detail">{t('planner.bomPowerAndFlux', { watts: Math.round(bom.watts * 10) / 10, lumens: Math.round(bom.lumens) })}</p>}
      {needs && needs.systems.length > 0 && <InstallationNeedsSummary needs={needs} />}
    </section>
  );
}

/** "Installation needs": what the electrician and the fitter must know, per system and in total. */
function InstallationNeedsSummary({ needs }: { needs: InstallationNeeds }) {
  const { t } = useI18n();
  const watts = (w: number) => Number(formatWatts(w));
  return (
    <div data-testid="installation-needs">
      <h3>{t('planner.installationNeeds')}</h3>
      <p className="preset-detail" data-testid="installation-totals">
        {t('planner.installationFeeds', { count: needs.feeds })}, {t('planner.installationFixings', { count: needs.ceilingFixings })}, {t('planner.installationLoad', { watts: watts(needs.totalLoad) })}
      </p>
      <ul className="installation-needs">
        {needs.systems.map((s, i) => (
          <li key={s.systemId}>
            {t(s.mounting === 'surface' ? 'planner.installationSystemSurface' : 'planner.installationSystemSuspended', { n: i + 1, count: s.ceilingFixings })}{' '}
            {s.feeds.map((f, k) => t('planner.installationFeed', { n: k + 1, load: watts(f.load), capacity: watts(f.capacity), driver: f.driver.name, output: f.driver.output })).join('; ')}
          </li>
        ))}
      </ul>
    </div>
  );
}
