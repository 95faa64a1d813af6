// The bill of materials the repository's own model gives for the consumer pages' configuration
// (the default catalog, a 6 × 4.5 × 3 m room, the preset 'single'): the reference the packed
// package's two doors are compared with (consumer.spec.ts). Run by scripts/checkPackage.mjs through tsx.
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { attemptAction } from '../src/core/model/actions/actionDefinitions';
import { createConfiguration } from '../src/core/model/configuration/configuration';
import { billOfMaterials } from '../src/core/model/power/billOfMaterials';

const outcome = attemptAction(createConfiguration({ width: 6, depth: 4.5, height: 3 }), 'placePreset', { presetId: 'single' }, defaultCatalog);
if (!outcome.ok) throw new Error(`placePreset single refused: ${outcome.reason}`);
const bom = billOfMaterials(outcome.next, defaultCatalog);
process.stdout.write(JSON.stringify({ total: bom.total, currency: bom.currency, articles: bom.lines.map((l) => `${l.count}×${l.article}`) }));
