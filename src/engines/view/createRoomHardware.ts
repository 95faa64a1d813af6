import * as THREE from 'three';
import type { Rgb } from '../../core/model/lightingScene';
import { hardwareFragment, hardwareVertex } from '../../../shaders/hardwareShading.glsl';
import type { Fixtures } from './fixtures';
import { hardwareBoxes, type HardwareBox } from './hardwareBoxes';

const COLORS: Record<HardwareBox['part'], Rgb> = {
  rail: [0.16, 0.16, 0.17],
  moduleOn: [0.98, 0.95, 0.86],
  moduleOff: [0.45, 0.45, 0.45],
  cable: [0.3, 0.3, 0.3],
};

/** The drawn hardware (rails, modules, cables) as a three.js group of flat-shaded boxes, rebuilt on each setFixtures. */
export interface RoomHardware {
  readonly group: THREE.Group;
  setFixtures(fixtures: Fixtures): void;
  /** Draw one module in the selection colour (null: none); kept across setFixtures. */
  setSelectedModule(id: string | null): void;
  dispose(): void;
}

/** The UI's accent blue (the plan's selection colour), for the selected module. */
const SELECTED: Rgb = [0.16, 0.56, 0.98];

export function createRoomHardware(): RoomHardware {
  const group = new THREE.Group();
  const materials = Object.fromEntries(
    Object.entries(COLORS).map(([part, color]) => [
      part,
      new THREE.ShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader: hardwareVertex, fragmentShader: hardwareFragment, uniforms: { uColor: { value: new THREE.Vector3(...color) } } }),
    ]),
  ) as Record<HardwareBox['part'], THREE.ShaderMaterial>;
  const selectedMaterial = new THREE.ShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader: hardwareVertex, fragmentShader: hardwareFragment, uniforms: { uColor: { value: new THREE.Vector3(...SELECTED) } } });
  let selected: string | null = null;
  const parts = new Map<THREE.Mesh, HardwareBox['part']>();
  const paint = () => {
    for (const [mesh, part] of parts) mesh.material = mesh.name === `module:${selected}` ? selectedMaterial : materials[part];
  };
  const clear = () => {
    for (const child of [...group.children]) {
      group.remove(child);
      (child as THREE.Mesh).geometry?.dispose();
    }
    parts.clear();
  };
  return {
    group,
    setFixtures(fixtures) {
      clear();
      for (const box of hardwareBoxes(fixtures)) {
        const mesh = new THREE.Mesh(new THREE.BoxGeometry(...box.size), materials[box.part]);
        mesh.position.set(...box.position);
        mesh.rotation.y = box.yaw;
        mesh.name = box.name;
        group.add(mesh);
        parts.set(mesh, box.part);
      }
      paint();
    },
    setSelectedModule(id) {
      selected = id;
      paint();
    },
    dispose() {
      clear();
      for (const m of Object.values(materials)) m.dispose();
      selectedMaterial.dispose();
    },
  };
}
