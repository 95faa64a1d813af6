import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakeReport } from './bakeJob';
import type { BakeSettings } from './bakeSettings';
import type { FluxRecord } from './fluxRecord';
import type { BrightSummary } from './selectBrightPatchesOnGpu';
import type { SurfaceLayout } from './surfaceLayout';
import type { ObjectReportEntry } from './objects/objectPassReport';
import { tailFactor } from './tailFactor';

/** What a job knows when its report is asked for. */
export interface BakeFacts {
  settings: BakeSettings;
  layouts: readonly SurfaceLayout[];
  luminaires: number;
  pointSources: number;
  directSkipped: SurfaceName[];
  indirectEnabled: boolean;
  /** The bright-patch selection (null: the pass did not run). */
  brightSelection: BrightSummary | null;
  bouncesComputed: number;
  /** Flux records 0..bouncesComputed (fluxRecord.ts), read back from the GPU. */
  records: readonly FluxRecord[];
  linearFiltering: boolean;
  shaders: BakeReport['shaders'];
  timings: BakeReport['timings_ms'];
  readbacks: BakeReport['readbacks'];
  /** Per-object statistics (scenes with objects only). */
  objects?: ObjectReportEntry[];
}

/** The bake report (bakeJob.ts, docs/baker.md "report.json"); timings and read-backs are copied as they are now. */
export function bakeReport(f: BakeFacts): BakeReport {
  const lastRatio = f.records[f.bouncesComputed].ratio;
  const selection = f.brightSelection;
  return {
    settings: f.settings,
    texels: Object.fromEntries(f.layouts.map((l) => [l.name, [l.width, l.height]])) as BakeReport['texels'],
    totalTexels: f.layouts.reduce((n, l) => n + l.width * l.height, 0),
    luminaires: f.luminaires,
    pointSources: f.pointSources,
    directSkipped: f.directSkipped,
    indirectEnabled: f.indirectEnabled,
    brightPatches: selection ? { ...selection } : { count: 0, peakedness: 1, residualPeakedness: 1 },
    samplesPerTexelPerBounce: f.indirectEnabled ? f.settings.samples : 0,
    bouncesComputed: f.bouncesComputed,
    bounceFlux: f.records.map((r) => r.fluxY),
    tailRatio: lastRatio,
    tailFactor: f.indirectEnabled && f.settings.tail ? tailFactor(lastRatio) : [0, 0, 0],
    linearFiltering: f.linearFiltering,
    shaders: f.shaders,
    timings_ms: { ...f.timings },
    readbacks: { ...f.readbacks },
    ...(f.objects ? { objects: f.objects } : {}),
  };
}
