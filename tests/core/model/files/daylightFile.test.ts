/** Scene file version 10 (issue 30): daylight and a window's glazing in files and share links, the step from version 9, and the lighting scene they give. */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../../src/core/catalog/defaultCatalog';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { lightingSceneJson } from '../../../../src/core/model/lightingScene/lightingSceneJson';
import { parseLightingScene } from '../../../../src/core/model/lightingScene/parseLightingScene';
import { sceneTextNeedsLazyModel } from '../../../../src/core/model/configuration/roomShapeSupport';
import { solarPosition } from '../../../../src/core/daylight/solarPosition';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { bakeDaylightOf } from '../../../../src/engines/bake/daylight/sceneDaylight';
import { GLAZING_PRESETS } from '../../../../src/core/daylight/glazing';

const frozen = (name: string) => readFileSync(`tests/fixtures/formats/${name}`, 'utf8');
const v10 = frozen('configuration-v10.luxbox.json');
const config = deserializeConfiguration(v10, defaultCatalog);
const withDaylight = (c: Configuration, d: Partial<NonNullable<Configuration['daylight']>>): Configuration => ({ ...c, daylight: { ...c.daylight!, ...d } });

describe('daylight in files', () => {
  it('the frozen version-10 file keeps its daylight and its window glazing, and a share link carries both', () => {
    expect(config.daylight).toEqual({ on: true, place: { city: 'Zurich' }, date: '2026-12-21', time: '17:00', sky: 'cie-clear', groundReflectance: 0.25 });
    expect(config.room.shape!.openings[1]).toMatchObject({ kind: 'window', transmittance: 'triple' });
    const shared = { ...config, objects: config.objects.filter((o) => o.source.kind === 'library'), importedMeshes: {} };
    const again = decodeShareString(encodeShareString(shared, defaultCatalog), defaultCatalog);
    expect(again.daylight).toEqual(config.daylight);
    expect(again.room).toEqual(config.room);
  });

  it('a version-9 file reads as version 10 without daylight, and is written back as version 10', () => {
    const v9 = deserializeConfiguration(frozen('configuration-v9.luxbox.json'), defaultCatalog);
    expect(v9.daylight).toBeUndefined();
    expect(v9.room.shape!.openings.every((o) => o.transmittance === undefined)).toBe(true);
    expect(JSON.parse(serializeConfiguration(v9, defaultCatalog)).version).toBe(10);
  });

  it('daylight or glazing in an older file is refused, naming the version the file says', () => {
    const doc10 = JSON.parse(v10);
    const v9 = JSON.parse(frozen('configuration-v9.luxbox.json'));
    v9.configuration.daylight = doc10.configuration.daylight;
    expect(() => deserializeConfiguration(JSON.stringify(v9), defaultCatalog, 'old.luxbox.json')).toThrow('old.luxbox.json: configuration.daylight: needs "version": 10 (this file says version 9)');
    const glazed = JSON.parse(frozen('configuration-v9.luxbox.json'));
    glazed.configuration.room.shape.openings[1].transmittance = 0.7;
    expect(() => deserializeConfiguration(JSON.stringify(glazed), defaultCatalog, 'old.luxbox.json')).toThrow('old.luxbox.json: configuration.room.shape.openings[1].transmittance: needs "version": 10 (this file says version 9)');
  });

  it('the reader refuses impossible daylight with the field and the rule', () => {
    const refused = (edit: (d: Record<string, unknown>) => void) => {
      const doc = JSON.parse(v10);
      edit(doc.configuration);
      return () => deserializeConfiguration(JSON.stringify(doc), defaultCatalog, 'a.json');
    };
    expect(refused((c) => ((c.daylight as Record<string, unknown>).date = '2026-02-30'))).toThrow("a.json: configuration.daylight.date: '2026-02-30' is not a day between 1901 and 2099 written YYYY-MM-DD");
    expect(refused((c) => ((c.daylight as Record<string, unknown>).time = '24:00'))).toThrow("a.json: configuration.daylight.time: '24:00' is not a clock time 00:00 to 23:59");
    expect(refused((c) => ((c.daylight as Record<string, unknown>).place = { city: 'Atlantis' }))).toThrow("a.json: configuration.daylight.place.city: 'Atlantis' is not a city of the list");
    expect(refused((c) => ((c.daylight as Record<string, unknown>).place = { latitude: 95, longitude: 8, timeZone: 1 }))).toThrow('a.json: configuration.daylight.place.latitude: the latitude must be between -90 and 90 ° (got 95)');
    expect(refused((c) => ((c.daylight as Record<string, unknown>).groundReflectance = 1))).toThrow("a.json: configuration.daylight.groundReflectance: the ground's reflectance must be at least 0 and below 1 (got 1)");
    expect(refused((c) => ((c.daylight as Record<string, unknown>).sky = 'cloudy'))).toThrow(/^a\.json: configuration\.daylight\.sky: /);
    expect(refused((c) => ((c.daylight as Record<string, unknown>).sunny = true))).toThrow("a.json: configuration.daylight.sunny: unknown field 'sunny'");
    expect(refused((c) => ((c.room as { shape: { openings: Record<string, unknown>[] } }).shape.openings[1].transmittance = 1.2))).toThrow(
      'a.json: configuration.room.shape.openings[1].transmittance: the glazing of window 1 must be single, double, triple or a transmittance from 0 to 1 (got 1.2)',
    );
    expect(refused((c) => ((c.room as { shape: { openings: Record<string, unknown>[] } }).shape.openings[0].transmittance = 'double'))).toThrow(
      'a.json: configuration.room.shape.openings[0].transmittance: opening 0 is a door; only a window has glazing',
    );
  });

  it('a file with daylight asks for the lazy chunk before it is read, even in a box room', () => {
    const box = serializeConfiguration({ ...createConfiguration(), daylight: config.daylight }, defaultCatalog);
    expect(sceneTextNeedsLazyModel(box)).toBe(true);
    expect(deserializeConfiguration(box, defaultCatalog).daylight).toEqual(config.daylight);
    expect(sceneTextNeedsLazyModel(serializeConfiguration(createConfiguration(), defaultCatalog))).toBe(false);
  });
});

describe('the lighting scene and the bake of a configuration with daylight', () => {
  it('10:00 on 21 June in Zurich: a clear sky with the sun at the clock time of summer time (UTC+2), the glazing by opening', () => {
    const june = withDaylight(config, { date: '2026-06-21', time: '10:00' });
    const scene = toLightingScene(june, defaultCatalog);
    const sky = scene.daylight!.sky!;
    expect(sky).toMatchObject({ type: 'cie-clear', groundReflectance: 0.25, sun: { city: 'Zurich', latitude: 47.4, longitude: 8.5, timeZone: 2, year: 2026, month: 6, day: 21, hours: 10 } });
    expect(scene.daylight!.transmittance).toEqual({ 1: 'triple' });
    // The same sun as NOAA's algorithm at 08:00 UTC (independently: UTC+0 at 8 h).
    const utc = solarPosition({ latitude: 47.4, longitude: 8.5, timeZone: 0 }, { year: 2026, month: 6, day: 21, hours: 8 });
    const bake = bakeDaylightOf(scene)!;
    expect(bake.conditions.position!.elevation).toBeCloseTo(utc.elevation, 6);
    expect(bake.conditions.position!.azimuth).toBeCloseTo(utc.azimuth, 6);
    expect(bake.daylight.sun).not.toBeNull();
    expect(bake.daylight.glazing.get(1)!.normalTransmittance).toBe(GLAZING_PRESETS.triple.normalTransmittance);
    // Written as the CLI's scene and read again: the same sky.
    const read = parseLightingScene(JSON.parse(JSON.stringify(lightingSceneJson(scene))), 'scene.json');
    expect(read.daylight!.sky!.type).toBe('cie-clear');
    expect(read.daylight!.sky!.sun).toMatchObject({ latitude: 47.4, longitude: 8.5, timeZone: 2, hours: 10 });
    expect(read.daylight!.transmittance).toEqual({ 1: 'triple' });
  });

  it('17:00 on 21 December (after sunset), or daylight off: no sky, the glazing stays (and after sunset the ground, for the daylight factor)', () => {
    const dusk = toLightingScene(config, defaultCatalog);
    expect(dusk.daylight).toEqual({ windows: [], transmittance: { 1: 'triple' }, groundReflectance: 0.25 });
    expect(bakeDaylightOf(dusk)).toBeNull();
    const off = toLightingScene(withDaylight(config, { on: false, date: '2026-06-21', time: '10:00' }), defaultCatalog);
    expect(off.daylight!.sky).toBeUndefined();
    expect(off.daylight!.groundReflectance).toBeUndefined();
  });

  it('coordinates keep their fixed offset; an overcast sky has no direct sun', () => {
    const scene = toLightingScene(withDaylight(config, { place: { latitude: 40.7, longitude: -74, timeZone: -4 }, date: '2026-07-04', time: '12:00', sky: 'cie-overcast' }), defaultCatalog);
    expect(scene.daylight!.sky!.sun).toMatchObject({ latitude: 40.7, longitude: -74, timeZone: -4, hours: 12 });
    expect(scene.daylight!.sky!.sun!.city).toBeUndefined();
    expect(bakeDaylightOf(scene)!.daylight.sun).toBeNull();
  });

  it('a room without a shape has no windows: no daylight in its scene', () => {
    expect(toLightingScene({ ...createConfiguration(), daylight: { ...config.daylight!, date: '2026-06-21', time: '12:00' } }, defaultCatalog).daylight).toBeUndefined();
  });
});
