/** The daylight part of `luxbox bench` as markdown (docs/benchmarks.md): its tables, the machine line, and the splice that rewrites only its own section. */
import { describe, expect, it } from 'vitest';
import { spliceSection } from '../../../src/hosts/bench/benchMarkdown';
import { DAYLIGHT_LADDER, DAYLIGHT_MARKERS, DAYLIGHT_SCENES, daylightSection, type DaylightBenchScenePart } from '../../../src/hosts/bench/daylightBench';
import type { MachineInfo } from '../../../src/hosts/bench/machineInfo';

const machine: MachineInfo = { date: '2026-11-27T17:00:00.000Z', cpuModel: 'Test CPU', cores: 2, memoryGiB: 8, os: 'Linux', node: 'v20', glVersion: 'WebGL 2.0', glRenderer: 'Mesa — llvmpipe' };
const parts: DaylightBenchScenePart[] = DAYLIGHT_SCENES.map((scene, i) => ({
  scene,
  patches: 1000 + i,
  referenceMs: 5000,
  rows: DAYLIGHT_LADDER.map((quality, k) => ({ scene: scene.name, quality, bakeMs: 100 * (k + 1), directMs: 10, points: 300, nearEdge: 5, sunEdge: 2, directRms: 0.004, directMax: 0.01, totalRms: 0.015 + k / 1000, totalMax: 0.1 })),
}));

describe('bench --daylight section', () => {
  it('has one row per scene and rung, the machine and the date, and replaces only its own section', () => {
    const section = daylightSection(parts, machine);
    const rows = section.split('\n').filter((l) => /^\| (box-overcast|box-sun|l-overcast) \|/.test(l));
    expect(rows).toHaveLength(DAYLIGHT_SCENES.length * DAYLIGHT_LADDER.length);
    expect(rows[1]).toBe('| box-overcast | 0.1 m | 64 | 4 | 200 ms | 10 ms | 300 (5, 2) | 0.40 % / 1.00 % | 1.60 % | 10.00 % |');
    expect(section).toContain('Machine: Test CPU, 2 cores, 8 GiB');
    expect(section).toContain('2026-11-27 17:00 UTC');
    const doc = `# Benchmarks\n\nother text\n\n${DAYLIGHT_MARKERS[0]}\nold\n${DAYLIGHT_MARKERS[1]}\n\ntail\n`;
    const spliced = spliceSection(doc, section, DAYLIGHT_MARKERS);
    expect(spliced).toContain('other text');
    expect(spliced).toContain('tail');
    expect(spliced).not.toContain('\nold\n');
    expect(spliced.split(DAYLIGHT_MARKERS[0])).toHaveLength(2);
  });
});
