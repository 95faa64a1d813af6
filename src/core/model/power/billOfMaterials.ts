/**
 * Bill of materials and price, computed live from the configuration.
 * Money is summed in integer cents so totals are exact; unit prices are the
 * catalog's, rails priced by length (base + perMetre·L, rounded to cents).
 * Counting rules (docs/model.md): per system one feed kit and one driver (its
 * article) per power feed; one suspension kit per derived suspension point, or
 * one surface clip per clip point when the system is on the ceiling
 * (suspensionPoints.ts); one connector per connector node (a T or X once for its branches); one rail article per distinct
 * length; one module article per type, beam and colour temperature; one filter article per colour
 * filter in front of a module (docs/colour-filters.md).
 */
import { findBeam, findConnector, findDriver, findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { findColourFilter } from '../../colour/colourFilterLibrary';
import { filterAccessory, filterLabel } from '../modules/moduleFilter';
import type { Configuration } from '../configuration/configuration';
import { firstNodeJoints, jointParent } from '../rails/railTree';
import { suspensionCoordinates } from '../rails/suspensionPoints';
import { InputError } from '../../inputError';

export interface BomLine {
  readonly article: string;
  readonly name: string;
  readonly count: number;
  /** Currency units (catalog currency). */
  readonly unitPrice: number;
  readonly total: number;
  readonly kind: 'rail' | 'connector' | 'suspension' | 'feed' | 'driver' | 'module' | 'filter';
}

export interface BillOfMaterials {
  readonly currency: string;
  readonly lines: readonly BomLine[];
  readonly total: number;
  /** Sum of module input power, watts (for the shop page). */
  readonly watts: number;
  /** Sum of module lumens (before dimming). */
  readonly lumens: number;
}

const cents = (x: number) => Math.round(x * 100);

export function railUnitPrice(length: number, catalog: Catalog): number {
  return cents(catalog.rail.price.base + catalog.rail.price.perMetre * length) / 100;
}

export function billOfMaterials(config: Configuration, catalog: Catalog): BillOfMaterials {
  const lines = new Map<string, { article: string; name: string; count: number; unitCents: number; kind: BomLine['kind'] }>();
  const add = (article: string, name: string, unit: number, kind: BomLine['kind'], count = 1) => {
    const line = lines.get(article);
    if (line) line.count += count;
    else lines.set(article, { article, name, count, unitCents: cents(unit), kind });
  };
  let watts = 0;
  let lumens = 0;
  for (const s of config.systems) {
    for (const f of s.feeds) {
      add(catalog.feed.article, catalog.feed.name, catalog.feed.price, 'feed');
      const driver = findDriver(catalog, f.driver);
      add(driver.article, `${driver.name} driver, ${driver.capacity} W ${driver.output}`, driver.price, 'driver');
    }
    const fixing = s.mounting === 'surface' ? catalog.surfaceMount : catalog.suspension;
    add(fixing.article, fixing.name, fixing.price, 'suspension', suspensionCoordinates(s, catalog).length);
    // One connector per node: the branches of a T or X share it (railTree.ts).
    const first = firstNodeJoints(s);
    s.joints.forEach((j, k) => {
      if (first[jointParent(j, k)] !== k) return;
      const con = findConnector(catalog, j.connector);
      add(con.article, con.name, con.price, 'connector');
    });
    for (const r of s.rails) {
      const mm = Math.round(r.length * 1000);
      add(`${catalog.rail.article}-${mm}`, `${catalog.rail.name} ${(mm / 1000).toFixed(2)} m`, railUnitPrice(r.length, catalog), 'rail');
      for (const m of r.modules) {
        const type = findModuleType(catalog, m.type);
        const beam = findBeam(type, m.beam);
        add(`${beam.article}-${m.cct}`, `${type.name}, ${beam.label}, ${m.cct} K`, beam.price, 'module');
        if (m.filter !== undefined) {
          const accessory = filterAccessory(catalog, m.filter);
          if (!accessory) throw new InputError(`unknown colour filter '${m.filter}' (catalog ${catalog.id})`);
          add(accessory.article, `${filterLabel(findColourFilter(m.filter))} colour filter`, accessory.price, 'filter');
        }
        watts += beam.watts;
        lumens += beam.lumens;
      }
    }
  }
  const order: BomLine['kind'][] = ['rail', 'connector', 'suspension', 'feed', 'driver', 'module', 'filter'];
  const out = [...lines.values()]
    .sort((a, b) => order.indexOf(a.kind) - order.indexOf(b.kind) || a.article.localeCompare(b.article))
    .map((l) => ({ article: l.article, name: l.name, count: l.count, unitPrice: l.unitCents / 100, total: (l.unitCents * l.count) / 100, kind: l.kind }));
  const totalCents = out.reduce((a, l) => a + cents(l.total), 0);
  return { currency: catalog.currency, lines: out, total: totalCents / 100, watts: Math.round(watts * 100) / 100, lumens };
}
