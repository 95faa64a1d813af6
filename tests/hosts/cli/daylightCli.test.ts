/**
 * `luxbox bake` on a scene with a window and a sky (tests/fixtures/scenes/daylight-room.json: the
 * daylight reference tests' 5 × 4 m room as a version-2 box with a south window, a CIE clear sky
 * at 10:00 in Zurich on the June solstice): report.json's daylight — the sun's position from
 * NOAA's algorithm, and the work plane's daylight factors against the independent daylight
 * reference (src/reference/solveDaylightReference.ts) at the same points.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { cityNamed } from '../../../src/core/daylight/cities';
import { daylightFactorStatistics } from '../../../src/core/daylight/daylightFactor';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { cieOvercastSky } from '../../../src/core/daylight/skies';
import { solarPosition } from '../../../src/core/daylight/solarPosition';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { workPlanePoints } from '../../../src/engines/bake/daylight/workPlaneDaylight';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import { daylightIlluminanceAt, solveDaylightReference } from '../../../src/reference/solveDaylightReference';
import { daylightBox } from '../../../src/hosts/bench/daylightBox';

const root = join(__dirname, '../../..');
const scene = join(root, 'tests/fixtures/scenes/daylight-room.json');

function luxbox(args: string[]) {
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

// The daylight box: its south window's u = 1.75 m from x = 0, so 1.75 m from the wall's first corner (5, 4) too.
const ROOM: RoomInput = daylightBox();

describe('luxbox bake: daylight in report.json', () => {
  it('reports the sun where NOAA puts it and work-plane daylight factors within 3 % of the reference', () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-daylight-'));
    const r = luxbox(['bake', scene, '--out', out, '--texel', '0.1']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const d = JSON.parse(readFileSync(join(out, 'report.json'), 'utf8')).daylight;
    const zurich = cityNamed('Zurich')!;
    const sun = solarPosition({ latitude: zurich.latitude, longitude: zurich.longitude, timeZone: 2 }, { year: 2026, month: 6, day: 21, hours: 10 });
    expect(d.sun.elevation).toBeCloseTo(sun.elevation, 3);
    expect(d.sun.azimuth).toBeCloseTo(sun.azimuth, 3);
    expect(d.sun.shining).toBe(true);
    expect(d.windows).toBe(1);
    expect(d.enteringFlux.sun).toBeGreaterThan(0);

    const reference = solveDaylightReference(ROOM, { sky: cieOvercastSky(10_000), sun: null, groundReflectance: 0.2, glazing: { 0: glazingFrom('double') } }, { patchSize: 0.25 });
    const points = workPlanePoints(normaliseRoom(ROOM));
    const df = points.map((p) => daylightIlluminanceAt(reference, p, [0, 1, 0]).total / 100);
    const expected = daylightFactorStatistics(df);
    const got = d.daylightFactor.workPlane;
    console.info(
      `work plane: ${points.length} points; DF average ${got.average} % (reference ${expected.average.toFixed(3)} %), median ${got.median} (${expected.median.toFixed(3)}), minimum ${got.minimum} (${expected.minimum.toFixed(3)}), share ≥ 2 % ${got.shareAtTarget} (${expected.shareAtTarget.toFixed(3)})`,
    );
    expect(d.workPlane.points).toBe(points.length);
    expect(Math.abs(got.average / expected.average - 1)).toBeLessThan(0.03);
    expect(Math.abs(got.median / expected.median - 1)).toBeLessThan(0.03);
    expect(Math.abs(got.minimum / expected.minimum - 1)).toBeLessThan(0.05);
    expect(Math.abs(got.shareAtTarget - expected.shareAtTarget)).toBeLessThan(0.05);
  });
});
