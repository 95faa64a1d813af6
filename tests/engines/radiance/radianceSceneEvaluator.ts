/**
 * A tiny, independent reading of an exported Radiance scene for the tests: it parses scene.rad's
 * primitives, reads the brightdata files, and evaluates the direct illuminance of the light
 * spheres at a point the way Radiance defines it (source.cal's src_theta/src_phi of the
 * transformed direction, linear interpolation of the data, A1 · value · πr² W/sr per sphere,
 * 179 lm/W). It shares no code with src/engines/radiance or the baker, so a test that compares
 * it with luxbox's directAtPoint checks the export's frame, rotation order, units and layout.
 */
type Vec3 = [number, number, number];

interface Primitive {
  modifier: string;
  type: string;
  name: string;
  strings: string[];
  reals: number[];
}

export function parseRad(text: string): Primitive[] {
  const tokens = text
    .split('\n')
    .filter((line) => !line.trimStart().startsWith('#'))
    .join(' ')
    .split(/\s+/)
    .filter(Boolean);
  const out: Primitive[] = [];
  let i = 0;
  while (i < tokens.length) {
    const [modifier, type, name] = tokens.slice(i, i + 3);
    i += 3;
    const ns = Number(tokens[i++]);
    const strings = tokens.slice(i, i + ns);
    i += ns;
    const ni = Number(tokens[i++]);
    i += ni;
    const nr = Number(tokens[i++]);
    const reals = tokens.slice(i, i + nr).map(Number);
    i += nr;
    out.push({ modifier, type, name, strings, reals });
  }
  return out;
}

interface DataFile {
  axes: number[][];
  values: number[];
}

export function parseDat(text: string): DataFile {
  const t = text.split(/\s+/).filter(Boolean).map(Number);
  let i = 0;
  const dims = t[i++];
  const axes: number[][] = [];
  for (let d = 0; d < dims; d++) {
    const [a, b, n] = [t[i++], t[i++], t[i++]];
    if (a === 0 && b === 0) {
      axes.push(t.slice(i, i + n));
      i += n;
    } else axes.push(Array.from({ length: n }, (_, k) => a + ((b - a) * k) / (n - 1)));
  }
  return { axes, values: t.slice(i) };
}

function interpolate(data: DataFile, coords: number[]): number {
  // Multilinear, last axis fastest (Radiance's data file order).
  const idx: [number, number, number][] = data.axes.map((axis, d) => {
    const x = Math.min(axis[axis.length - 1], Math.max(axis[0], coords[d]));
    let k = 0;
    while (k < axis.length - 2 && axis[k + 1] < x) k++;
    const f = axis[k + 1] === axis[k] ? 0 : (x - axis[k]) / (axis[k + 1] - axis[k]);
    return [k, k + 1, f];
  });
  let sum = 0;
  for (let corner = 0; corner < 1 << idx.length; corner++) {
    let w = 1;
    let flat = 0;
    for (let d = 0; d < idx.length; d++) {
      const hi = (corner >> d) & 1;
      w *= hi ? idx[d][2] : 1 - idx[d][2];
      flat = flat * data.axes[d].length + (hi ? idx[d][1] : idx[d][0]);
    }
    if (w > 0) sum += w * data.values[flat];
  }
  return sum;
}

const rot = (axis: 'x' | 'z', deg: number, v: Vec3): Vec3 => {
  const c = Math.cos((deg * Math.PI) / 180);
  const s = Math.sin((deg * Math.PI) / 180);
  return axis === 'z' ? [c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]] : [v[0], c * v[1] - s * v[2], s * v[1] + c * v[2]];
};

/** Direct illuminance (lux per RGB channel) at P with unit normal N, both in Radiance's frame. */
export function radianceDirect(files: ReadonlyMap<string, string>, point: Vec3, normal: Vec3): Vec3 {
  const prims = parseRad(files.get('scene.rad')!);
  const byName = new Map(prims.map((p) => [p.name, p]));
  const e: Vec3 = [0, 0, 0];
  for (const sphere of prims.filter((p) => p.type === 'sphere')) {
    const light = byName.get(sphere.modifier)!;
    const dist = byName.get(light.modifier)!;
    const [, datPath, , ...rest] = dist.strings;
    const vars = rest.filter((s) => s.startsWith('src_'));
    const transform = rest.slice(vars.length);
    const data = parseDat(files.get(datPath)!);
    const [cx, cy, cz, r] = sphere.reals;
    const v: Vec3 = [point[0] - cx, point[1] - cy, point[2] - cz];
    const d2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const d = Math.sqrt(d2);
    const cos = -(v[0] * normal[0] + v[1] * normal[1] + v[2] * normal[2]) / d;
    if (cos <= 0) continue;
    // The pattern was transformed by the arguments in order; undo them in reverse to get
    // the emitted direction in the source's own frame.
    let local: Vec3 = [v[0] / d, v[1] / d, v[2] / d];
    for (let k = transform.length - 2; k >= 0; k -= 2) local = rot(transform[k] === '-rz' ? 'z' : 'x', -Number(transform[k + 1]), local);
    // source.cal: D = −(emitted direction); src_theta = acos(Dz), src_phi = atan2(−Dy, −Dx).
    const theta = (Math.acos(Math.max(-1, Math.min(1, -local[2]))) * 180) / Math.PI;
    let phi = (Math.atan2(local[1], local[0]) * 180) / Math.PI;
    if (phi < 0) phi += 360;
    const coords = vars.map((name) => (name === 'src_theta' ? theta : phi));
    const wattsPerSr = dist.reals[0] * interpolate(data, coords) * Math.PI * r * r;
    for (let c = 0; c < 3; c++) e[c] += (179 * wattsPerSr * light.reals[c] * cos) / d2;
  }
  return e;
}
