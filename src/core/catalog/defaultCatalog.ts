/**
 * The catalog the app ships with: the JSON next to this file, validated at
 * load. A manufacturer replaces default-catalog.json (or passes its own catalog
 * to the store / embedding API); no code changes needed.
 */
import data from './default-catalog.json';
import { parseCatalog, type Catalog } from '../model/catalogSchema/catalogSchema';

export const defaultCatalog: Catalog = parseCatalog(data, 'src/core/catalog/default-catalog.json');
