/** What the steps of one GLDF product's conversion (gldfToModuleType.ts) share. */
import type { ModuleTypeSpec } from '../model/catalogSchema/moduleTypeSchema';
import type { ProductReport } from './gldfImportReport';
import type { GldfProductMapping } from './gldfMapping';
import type { GldfFile, GldfProduct, GldfVariant, LocaleTexts } from './gldfProduct';
import type { UploadZip } from './readUploadZip';

export interface ConvertOptions {
  mapping?: GldfProductMapping;
  mountings?: readonly string[];
  currency: string;
}

export interface ConvertedProduct {
  type: ModuleTypeSpec | null;
  files: { path: string; bytes: Uint8Array }[];
  report: ProductReport;
}

/** One product on its way to a module type: its inputs, the report and the files it fills, and how it records a default it assumed. */
export interface Conversion {
  product: GldfProduct;
  zip: UploadZip;
  options: ConvertOptions;
  map: GldfProductMapping;
  typeId: string;
  report: ProductReport;
  files: ConvertedProduct['files'];
  assume(field: string, value: string, why: string): void;
}

/** A variant that can become one beam × CCT of the type, with what it offers. */
export interface Accepted {
  variant: GldfVariant;
  photometryId: string;
  file: GldfFile;
  cct: number;
  cri?: number;
  flux: number;
  watts: number;
  kind: 'luminaire' | 'lamp';
  emitterName?: LocaleTexts;
  /** The light source states no CCT: GLDF_DEFAULTS.cct. */
  cctAssumed?: boolean;
}
