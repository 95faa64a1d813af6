import { furnishedTables } from './furnishedBench';
import { shapedRoomTables } from './shapedRoomBench';
import { daylightTables } from './daylightBench';
import type { BenchResult } from './runBench';

const pct = (e: number): string => (100 * e < 0.1 ? (100 * e).toFixed(3) : (100 * e).toFixed(2));
const ms = (t: number): string => (t >= 10_000 ? `${(t / 1000).toFixed(1)} s` : `${Math.round(t)} ms`);

/** The results as markdown tables (the part of docs/benchmarks.md that the bench writes). */
export function benchTables(r: BenchResult, svgName: string | null): string {
  const lines: string[] = [];
  const m = r.machine;
  lines.push(`Run: ${m.date}${r.quick ? ' (`--quick` smoke run)' : ''}, total ${ms(r.totalMs)}.`);
  lines.push('');
  lines.push(`Machine: ${m.cpuModel}, ${m.cores} logical cores, ${m.memoryGiB} GiB; ${m.os}; Node ${m.node}.`);
  lines.push(`GL: ${m.glVersion}; renderer ${m.glRenderer}.`);
  lines.push('');
  lines.push('#### Scenes and references');
  lines.push('');
  lines.push('| scene | luminaires | comparison points | reference patches | Gauss–Seidel sweeps | reference time | reference at 2× coarser patches vs this one (total RMS / max) |');
  lines.push('|---|---|---|---|---|---|---|');
  for (const s of r.scenes) {
    const change = s.referenceChange ? `${pct(s.referenceChange.rms)} % / ${pct(s.referenceChange.max)} % (${s.referenceChange.patch} m)` : '—';
    lines.push(
      `| ${s.scene.name}: ${s.scene.description} | ${s.luminaires} | ${s.points} (every ${s.scene.sampleSpacing} m) | ${s.referencePatches} (${s.scene.referencePatch} m) | ${s.referenceSweeps} | ${ms(s.referenceMs)} | ${change} |`,
    );
  }
  lines.push('');
  lines.push('#### Error against run time');
  lines.push('');
  lines.push(
    'Relative error of the baked maps, read as `luxbox probe` reads them, against the reference at the comparison points. Bake time is wall clock for `baker.bake` (all passes and the read-back; each timed bake follows an untimed warm-up bake with the same texel size and luminaires, so program compilation is excluded; the compile column shows what was left).',
  );
  lines.push('');
  lines.push(
    "Method: **bright patches** = today's default (texel-mean direct maps, bounce 1 from the brightest tiles by exact form factors, probe evaluates direct light at the point); **Monte Carlo only** = the method before issue #8 (texel-centre direct maps, cosine-sampled gather for every bounce, probe reads direct light from the maps).",
  );
  lines.push('');
  lines.push('| scene | method | rung | texel | samples | bounces | texels | bake time | of which compile | total RMS | total max | direct RMS | indirect RMS | mean total bake / ref (lx) |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|');
  for (const row of r.rows) {
    const q = row.quality;
    const rung = r.rows.filter((x) => x.scene === row.scene).indexOf(row) + 1;
    lines.push(
      `| ${row.scene.replace(/ \(Monte Carlo only\)$/, '')} | ${row.method === 'monte-carlo' ? 'Monte Carlo only' : 'bright patches'} | ${rung} | ${q.texelSize} m | ${q.samples} | ${q.bounces} | ${row.texels} | ${ms(row.bakeMs)} | ${ms(row.compileMs)} | ${pct(row.total.rms)} % | ${pct(row.total.max)} % | ${pct(row.direct.rms)} % | ${pct(row.indirect.rms)} % | ${row.meanBake.toFixed(1)} / ${row.meanReference.toFixed(1)} |`,
    );
  }
  lines.push('');
  const summary = stiffSummary(r);
  if (summary.length) {
    lines.push('#### Old against new at the default settings (0.025 m, 64 samples, 4 bounces)');
    lines.push('');
    lines.push('| scene | Monte Carlo only: RMS / max | its time | 4× samples: RMS / max | its time | bright patches: RMS / max | its time | time new / old |');
    lines.push('|---|---|---|---|---|---|---|---|');
    lines.push(...summary);
    lines.push('');
  }
  if (svgName) {
    lines.push(`![error versus bake time](${svgName})`);
    lines.push('');
  }
  lines.push(`#### Bake time against luminaires and texels (${r.scalingScene}, ${r.scalingQuality.samples} samples, ${r.scalingQuality.bounces} bounces)`);
  lines.push('');
  lines.push('| study | luminaires | point sources | texel | texels | bake time | of which compile | µs per texel |');
  lines.push('|---|---|---|---|---|---|---|---|');
  for (const s of r.scaling) {
    lines.push(`| ${s.study} | ${s.luminaires} | ${s.pointSources} | ${s.texelSize} m | ${s.texels} | ${ms(s.bakeMs)} | ${ms(s.compileMs)} | ${((1000 * (s.bakeMs - s.compileMs)) / s.texels).toFixed(1)} |`);
  }
  lines.push('');
  if (r.furnished && r.furnished.length > 0) {
    lines.push('#### Furnished rooms (objects, against the furnished CPU reference)');
    lines.push('');
    lines.push(furnishedTables(r.furnished));
    lines.push('');
  }
  if (r.shaped && r.shaped.length > 0) {
    lines.push('#### Rooms of any shape (the room reference; issue 29)');
    lines.push('');
    lines.push(shapedRoomTables(r.shaped));
    lines.push('');
  }
  if (r.daylight && r.daylight.length > 0) {
    lines.push('#### Daylight (the daylight reference; issue 30)');
    lines.push('');
    lines.push(daylightTables(r.daylight));
    lines.push('');
  }
  return lines.join('\n');
}

/**
 * `doc` with the bench's section replaced by `section` (between the markers),
 * or with it appended when the markers are absent; the rest is kept as is.
 */
export function spliceSection(doc: string, section: string, markers: readonly [string, string]): string {
  const block = `${markers[0]}\n${section.trim()}\n${markers[1]}\n`;
  const start = doc.indexOf(markers[0]);
  const end = doc.indexOf(markers[1]);
  if (start >= 0 && end > start) return doc.slice(0, start) + block + doc.slice(end + markers[1].length).replace(/^\n/, '');
  return (doc.trim() ? doc.replace(/\s*$/, '\n\n') : '# Benchmarks\n\n') + block;
}

const isDefault = (q: { texelSize: number; samples: number; bounces: number }, samples = 64) => q.texelSize === 0.025 && q.samples === samples && q.bounces === 4;

/** One line per scene that has both methods at the default rung. */
function stiffSummary(r: BenchResult): string[] {
  const out: string[] = [];
  for (const s of r.scenes) {
    const name = s.scene.name;
    const pick = (method: string, samples = 64) => r.rows.find((x) => x.method === method && x.scene.startsWith(name) && (x.scene === name || x.scene === `${name} (Monte Carlo only)`) && isDefault(x.quality, samples));
    const old = pick('monte-carlo');
    const now = pick('bright-patches');
    if (!old || !now) continue;
    const more = pick('monte-carlo', 256);
    const cell = (x: typeof old) => `${pct(x.total.rms)} % / ${pct(x.total.max)} % | ${ms(x.bakeMs)}`;
    out.push(`| ${name} | ${cell(old)} | ${more ? cell(more) : '— | —'} | ${cell(now)} | ${(now.bakeMs / old.bakeMs).toFixed(2)} |`);
  }
  return out;
}
