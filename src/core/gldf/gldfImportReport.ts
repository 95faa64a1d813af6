/**
 * What an import did, product by product (docs/gldf.md, "The import report"): the variants
 * imported (with the manufacturer's own article number and GTIN, which the catalog's
 * `<article>-<cct>` does not keep), the variants skipped and why, every value assumed because
 * neither the GLDF nor the mapping file gave it, and each variant's rated flux against the
 * flux integrated from its photometry.
 */
export interface ImportedVariant {
  variant: string;
  productNumber: string;
  gtin?: string;
  beam: string;
  cct: number;
  cri?: number;
  /** GLDF rated luminous flux, lm, and rated input power, W. */
  ratedFlux: number;
  ratedPower: number;
}

export interface FluxCheck {
  variant: string;
  beam: string;
  photometry: string;
  ratedFlux: number;
  /** Flux integrated from the photometry's candela grid (integrateFlux), lm. */
  integratedFlux: number;
  /** (integrated − rated) / rated, percent. */
  differencePercent: number;
  /** 'luminaire': the rated flux is the luminaire's (fixed light source), 5 % tolerance; 'lamp': lamp lumens, integrated/rated is the light output ratio. */
  kind: 'luminaire' | 'lamp';
  /** The photometry parser's own rule (lumensWarning): null when within it, else its sentence. */
  warning: string | null;
}

export interface ProductReport {
  source: string;
  uniqueProductId: string;
  /** The module type made, or null when no variant could be imported. */
  typeId: string | null;
  /** A type of that id was in the base catalog and was replaced. */
  replaced?: boolean;
  imported: ImportedVariant[];
  skipped: { variant: string; reason: string }[];
  assumed: { field: string; value: string; why: string }[];
  flux: FluxCheck[];
  /** Files written for this product (photometry, picture), relative to the catalog folder. */
  files: string[];
  notes: string[];
}

export interface GldfImportReport {
  catalog: string;
  products: ProductReport[];
  /** Mapping entries that matched nothing (a misspelt product or photometry id). */
  unusedMapping: string[];
}

const round = (x: number, digits = 1): string => String(Math.round(x * 10 ** digits) / 10 ** digits);

/** The report as lines of text (import-report.txt and the CLI's summary). */
export function formatImportReport(report: GldfImportReport): string {
  const out: string[] = [`Import into catalog '${report.catalog}'`];
  for (const p of report.products) {
    out.push('', `${p.source} (product ${p.uniqueProductId}): ${p.typeId ? `module type '${p.typeId}'${p.replaced ? ' (replaced the base catalog’s)' : ''}` : 'nothing imported'}`);
    for (const v of p.imported) out.push(`  imported ${v.variant} (${v.productNumber}${v.gtin ? `, GTIN ${v.gtin}` : ''}): beam '${v.beam}', ${v.cct} K${v.cri !== undefined ? `, CRI ${v.cri}` : ''}, ${v.ratedFlux} lm, ${v.ratedPower} W`);
    for (const s of p.skipped) out.push(`  skipped ${s.variant}: ${s.reason}`);
    for (const a of p.assumed) out.push(`  assumed ${a.field} = ${a.value}: ${a.why}`);
    for (const f of p.flux) {
      out.push(
        `  flux ${f.variant} (${f.photometry}): rated ${f.ratedFlux} lm, integrated ${round(f.integratedFlux)} lm (${f.differencePercent >= 0 ? '+' : ''}${round(f.differencePercent)} %)${f.warning ? `: ${f.warning}` : ', within tolerance'}`,
      );
    }
    for (const n of p.notes) out.push(`  note: ${n}`);
    for (const f of p.files) out.push(`  wrote ${f}`);
  }
  for (const u of report.unusedMapping) out.push('', `mapping: ${u}`);
  return out.join('\n') + '\n';
}
