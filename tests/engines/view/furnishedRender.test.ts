/**
 * A furnished room through `luxbox render`'s path (scene file → loadRenderInput → renderViews on
 * headless-gl with three.js): a dining table under a rail of spots. The table top must come out
 * brighter than the floor in its shadow, in the baked numbers (objectStats) and in the pixels
 * (a vertical line through the image from the table top down to the floor under the table).
 */
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { attemptAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../../../src/engines/relight/createRelightEngine';
import type { CameraPose } from '../../../src/engines/view/cameraPresets';
import { objectLightOf } from '../../../src/engines/view/objectLight';
import { objectStats } from '../../../src/engines/view/objectStats';
import { createRenderSession } from '../../../src/hosts/node/renderImage';
import { loadRenderInput } from '../../../src/hosts/node/renderInput';
import createGL from 'gl';

function act(config: Configuration, name: string, params: unknown): Configuration {
  const outcome = attemptAction(config, name, params, defaultCatalog);
  if (!outcome.ok) throw new Error(`${name} refused: ${outcome.reason}`);
  return outcome.next;
}

/** 5 × 4 × 2.8 m room, the single-rail preset at its centre, a dining table under it. */
function furnishedConfiguration(): Configuration {
  let c = createConfiguration({ width: 5, depth: 4, height: 2.8 });
  c = act(c, 'placePreset', { presetId: 'single' });
  c = act(c, 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 2.5, z: 2 } });
  return c;
}

const settings = { ...VIEWER_BAKE_SETTINGS, texelSize: 0.1, samples: 32, bounces: 2 };
const WIDTH = 320;
const HEIGHT = 240;
/** Side view from the south, a little above the table: the top and the floor under it (seen below the top's front edge) on one image column. */
const camera: CameraPose = { position: [2.5, 1.35, 4.0 - 0.05], target: [2.5, 0.45, 2.0], fov: 60 };

function pixelOf(point: [number, number, number]): [number, number] {
  const cam = new THREE.PerspectiveCamera(camera.fov, WIDTH / HEIGHT, 0.05, 500);
  cam.position.set(...camera.position);
  cam.up.set(0, 1, 0);
  cam.lookAt(new THREE.Vector3(...camera.target));
  cam.updateMatrixWorld();
  const p = new THREE.Vector3(...point).project(cam);
  return [Math.round(((p.x + 1) / 2) * WIDTH), Math.round(((1 - p.y) / 2) * HEIGHT)];
}

describe('a furnished room in luxbox render', () => {
  const dir = mkdtempSync(join(tmpdir(), 'luxbox-furnished-'));
  const file = join(dir, 'furnished.luxbox.json');
  writeFileSync(file, serializeConfiguration(furnishedConfiguration(), defaultCatalog));
  const input = loadRenderInput(file);

  it('reads the table from the configuration (object:<id>)', () => {
    expect(input.bakeScene.objects?.length).toBe(1);
    expect(input.scene.objects?.[0].mesh).toMatch(/^object:o\d+$/);
  });

  it('the table top is lit, the floor under it in shadow (baked numbers), and the pixels say the same', () => {
    // Baked numbers: the relit maps of the same engine and settings the render uses.
    const gl = createGL(8, 8, { createWebGL2Context: true }) as unknown as WebGL2RenderingContext;
    const engine = createRelightEngine(gl, settings);
    engine.setScene(input.bakeScene);
    engine.finish();
    const lit = engine.maps();
    const prepared = prepareObjects(input.bakeScene.objects!, { texelSize: engine.settings.texelSize, maxAtlasSize: engine.settings.maxTextureSize });
    const light = objectLightOf(lit);
    expect(light).not.toBeNull();
    const [table] = objectStats(lit, prepared, light!);
    engine.dispose();
    expect(table.top).not.toBeNull();
    expect(table.floorUnder).not.toBeNull();
    // Spots 2 m above the top: hundreds of lux on the top; the floor under it gets only what the room bounces round the top.
    expect(table.top!).toBeGreaterThan(3 * table.floorUnder!);

    const session = createRenderSession(WIDTH, HEIGHT);
    let pixels: Uint8Array;
    let png: Buffer;
    try {
      [{ pixels, png }] = session.renderViews(input, { width: WIDTH, height: HEIGHT, camera, exposureEv: 0, mode: 'light', settings }, [camera]);
    } finally {
      session.destroy();
    }
    const grey = (x: number, y: number) => {
      const o = 4 * (y * WIDTH + x);
      return 0.2126 * pixels[o] + 0.7152 * pixels[o + 1] + 0.0722 * pixels[o + 2];
    };
    // One image column through the table's middle: the top's centre and the floor under the table's centre.
    const [xTop, yTop] = pixelOf([2.5, 0.751, 2.0]);
    const [xFloor, yFloor] = pixelOf([2.5, 0.0, 2.0]);
    expect(Math.abs(xTop - xFloor)).toBeLessThanOrEqual(1);
    expect(yFloor).toBeGreaterThan(yTop + 10);
    const mean = (y0: number, y1: number) => {
      let s = 0;
      for (let y = y0; y <= y1; y++) for (let x = xTop - 2; x <= xTop + 2; x++) s += grey(x, y);
      return s / ((y1 - y0 + 1) * 5);
    };
    const top = mean(yTop - 2, yTop + 2);
    const floor = mean(yFloor - 2, yFloor + 2);
    // For a look: test-results/furnished/side.png (not compared: the light's noise moves pixels between runs of different settings).
    mkdirSync('test-results/furnished', { recursive: true });
    writeFileSync('test-results/furnished/side.png', png);
    console.log(
      `table top ${table.top!.toFixed(0)} lx, floor under ${table.floorUnder!.toFixed(0)} lx, object mean ${table.avg.toFixed(0)} lx; pixels: top ${top.toFixed(0)}, floor ${floor.toFixed(0)} at (${xTop}, ${yTop}) / (${xFloor}, ${yFloor})`,
    );
    expect(top).toBeGreaterThan(floor + 40);
  }, 240_000);
});
