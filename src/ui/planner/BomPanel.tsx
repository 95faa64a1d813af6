import type { BillOfMaterials } from '../../core/model/billOfMaterials';
import { formatMoney } from './formatMoney';

export interface BomPanelProps {
  bom: BillOfMaterials;
  locale?: string;
}

/** Live bill of materials with prices (the configurator paper's planned live price): article, count, unit price, total. */
export function BomPanel({ bom, locale }: BomPanelProps) {
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
    </section>
  );
}
