import type { BillOfMaterials } from '../../core/model/billOfMaterials';
import type { InstallationNeeds } from '../../core/model/installationNeeds';
import { formatWatts } from '../../core/model/feedLoads';
import { formatMoney } from './formatMoney';

export interface BomPanelProps {
  bom: BillOfMaterials;
  locale?: string;
  /** The installer's summary before the cart hand-off (feeds, ceiling fixings, load); omitted: not shown. */
  needs?: InstallationNeeds;
}

/** Live bill of materials with prices (the configurator paper's planned live price): article, count, unit price, total. */
export function BomPanel({ bom, locale, needs }: BomPanelProps) {
  const money = (x: number) => formatMoney(x, bom.currency, locale);
  return (
    <section className="panel-section" aria-labelledby="bom-title" data-testid="bom">
      <h2 id="bom-title">Bill of materials</h2>
      {bom.lines.length === 0 ? (
        <p className="empty-note">Nothing placed yet. Choose a preset above.</p>
      ) : (
        <table className="bom-table">
          <thead>
            <tr>
              <th scope="col">Article</th>
              <th scope="col" className="num">
                Qty
              </th>
              <th scope="col" className="num">
                Unit
              </th>
              <th scope="col" className="num">
                Total
              </th>
            </tr>
          </thead>
          <tbody>
            {bom.lines.map((l) => (
              <tr key={l.article}>
                <td>
                  <div>{l.name}</div>
                  <div className="preset-detail">{l.article}</div>
                </td>
                <td className="num">{l.count}</td>
                <td className="num">{money(l.unitPrice)}</td>
                <td className="num">{money(l.total)}</td>
              </tr>
            ))}
          </tbody>
          <tfoot>
            <tr>
              <td colSpan={3}>Total ({bom.currency})</td>
              <td className="num" data-testid="bom-total">
                {money(bom.total)}
              </td>
            </tr>
          </tfoot>
        </table>
      )}
      {bom.lines.length > 0 && (
        <p className="preset-detail">
          {Math.round(bom.watts * 10) / 10} W, {Math.round(bom.lumens)} lm in total
        </p>
      )}
      {needs && needs.systems.length > 0 && <InstallationNeedsSummary needs={needs} />}
    </section>
  );
}

/** "Installation needs": what the electrician and the fitter must know, per system and in total. */
function InstallationNeedsSummary({ needs }: { needs: InstallationNeeds }) {
  return (
    <div data-testid="installation-needs">
      <h3>Installation needs</h3>
      <p className="preset-detail" data-testid="installation-totals">
        {needs.feeds} power feed{needs.feeds === 1 ? '' : 's'}, {needs.ceilingFixings} ceiling fixing{needs.ceilingFixings === 1 ? '' : 's'}, {formatWatts(needs.totalLoad)} W in total
      </p>
      <ul className="installation-needs">
        {needs.systems.map((s, i) => (
          <li key={s.systemId}>
            System {i + 1} ({s.mounting === 'surface' ? 'on the ceiling' : 'suspended'}, {s.ceilingFixings} fixings):{' '}
            {s.feeds.map((f) => `${f.label}: ${formatWatts(f.load)} / ${formatWatts(f.capacity)} W (${f.driver.name}, ${f.driver.output})`).join('; ')}
          </li>
        ))}
      </ul>
    </div>
  );
}
