import type { BomLine } from '../../core/model/power/billOfMaterials';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Format } from './createFormat';
import type { Language } from './languages';
import { localLabel, localName } from './localName';
import type { Translate } from './messageTypes';

/**
 * A bill-of-materials line's name in the UI language, rebuilt from the catalog entry its article
 * names (billOfMaterials.ts writes the English one): the module type and beam with the CCT, the
 * rail with its length, a connector, fixing or feed kit by its translated name, a driver with its
 * power. A line the catalog cannot explain keeps the name it has.
 */
export function bomLineName(line: BomLine, catalog: Catalog, language: Language, t: Translate, format: Format): string {
  switch (line.kind) {
    case 'module':
      for (const type of catalog.moduleTypes) {
        for (const beam of type.beams) {
          const prefix = `${beam.article}-`;
          if (line.article.startsWith(prefix)) return t('planner.bomModule', { type: localName(type, language), beam: localLabel(beam, language), cct: line.article.slice(prefix.length) });
        }
      }
      return line.name;
    case 'rail': {
      const prefix = `${catalog.rail.article}-`;
      const mm = Number(line.article.slice(prefix.length));
      return line.article.startsWith(prefix) && Number.isFinite(mm) ? `${localName(catalog.rail, language)} ${format.metres(mm / 1000)}` : line.name;
    }
    case 'connector': {
      const con = catalog.connectors.find((c) => c.article === line.article);
      return con ? localName(con, language) : line.name;
    }
    case 'suspension': {
      const fixing = [catalog.suspension, catalog.surfaceMount].find((f) => f.article === line.article);
      return fixing ? localName(fixing, language) : line.name;
    }
    case 'feed':
      return line.article === catalog.feed.article ? localName(catalog.feed, language) : line.name;
    case 'driver': {
      const d = catalog.drivers.find((x) => x.article === line.article);
      return d ? t('planner.bomDriver', { name: d.name, capacity: d.capacity, output: d.output }) : line.name;
    }
    default:
      return line.name;
  }
}
