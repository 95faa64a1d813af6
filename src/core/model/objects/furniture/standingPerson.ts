/**
 * The library's standing person (issue 26): a recognisable human of 1.75 m, made of the closed
 * convex parts every library item is made of (meshParts.ts), so the baker lights it like any other
 * object. Proportions of an adult man, 50th percentile, stature H = 1.75 m (A. R. Tilley, Henry
 * Dreyfuss Associates, "The Measure of Man and Woman", rev. ed. 2002, and NASA-STD-3000 vol. I,
 * table 3.3.1.3-2, rounded to the centimetre): head (chin to crown) H/7.5 = 23 cm, 15.5 cm broad
 * and 19.5 cm long; shoulder (acromion) height 0.82 H = 1.44 m; elbow 0.62 H = 1.09 m; wrist
 * 0.49 H = 0.86 m; fingertips 0.39 H = 0.68 m; crotch 0.47 H = 0.82 m; knee 0.28 H = 0.49 m;
 * hips 35 cm broad; shoulders over the deltoids 50 cm; shoe 25.5 cm long. Round parts are rings
 * of circles and ellipses (tapered limbs with a calf and a forearm swell, an egg-shaped head with
 * hair over its crown and back, a nose that says which way it faces). Bounding box 50 × 30 × 175 cm,
 * origin on the floor between the feet, front toward +z (the library's frame).
 */
import { ellipsoidRings, ringedPart, type MeshPart, type Ring } from './meshParts';

/** Stature, metres: the crown of the hair. */
export const PERSON_STATURE = 1.75;

/** Chin and crown of the head (skin), metres: H/7.5 apart (the classical eight-head canon's 7.5 for an average adult). */
export const PERSON_HEAD = { chin: 1.52, crown: 1.7467 } as const;

/** A round limb along y through (x, z): circles of radius r at the given heights (bottom to top), 8 segments round. */
function limb(material: string, x: number, z: number, profile: readonly (readonly [y: number, r: number])[]): MeshPart {
  const rings: Ring[] = profile.map(([y, r]) => [y, r, r, r]);
  return ringedPart(material, x, z, rings, 2);
}

/** An ellipsoid centred at (x, yc, z), semi-axes hx, ay, hz; `k` rings a half, corners of `segments` arcs. */
function ellipsoid(material: string, x: number, yc: number, z: number, hx: number, ay: number, hz: number, k = 3, segments = 3): MeshPart {
  return ringedPart(material, x, z, ellipsoidRings(yc, ay, hx, hz, k), segments, yc - ay, yc + ay);
}

/** Both sides of the body: the part for the left (x < 0) and the right. */
const bothSides = (make: (side: number) => MeshPart): MeshPart[] => [make(-1), make(1)];

/** Legs from the floor to the hips: shoes, and trouser legs tapering from the hip to the ankle over the knee, the pelvis. */
function legs(): MeshPart[] {
  const x = 0.09;
  const z = -0.035;
  return [
    ...bothSides((s) =>
      ringedPart(
        'shoes',
        s * x,
        0.0225,
        [
          [0, 0.048, 0.1275, 0.045],
          [0.085, 0.048, 0.1275, 0.045],
        ],
        1,
      ),
    ),
    ...bothSides((s) =>
      limb('trousers', s * x, z, [
        [0.06, 0.042],
        [0.51, 0.056],
      ]),
    ),
    ...bothSides((s) =>
      limb('trousers', s * x, z, [
        [0.47, 0.056],
        [0.86, 0.085],
      ]),
    ),
    ringedPart(
      'trousers',
      0,
      -0.03,
      [
        [0.8, 0.165, 0.12, 0.1],
        [1.03, 0.155, 0.1, 0.09],
      ],
      1,
    ),
  ];
}

/** A hand hanging at the side, palm to the thigh: a flat tapered block from the wrist to the fingertips (k = 1: few flat faces). */
function hand(x: number): MeshPart {
  return ringedPart(
    'skin',
    x,
    0.0,
    [
      [0.68, 0.014, 0.032, 0.014],
      [0.86, 0.022, 0.042, 0.022],
    ],
    1,
  );
}

/** Chest and shoulders (shirt), arms hanging: upper arms in the sleeves, forearms and hands (skin). */
function torsoAndArms(): MeshPart[] {
  const arm = 0.204;
  return [
    ringedPart(
      'shirt',
      0,
      -0.02,
      [
        [1.0, 0.15, 0.095, 0.09],
        [1.2, 0.17, 0.11, 0.1],
        [1.36, 0.185, 0.11, 0.1],
        [1.44, 0.165, 0.095, 0.09],
        [1.48, 0.1, 0.07, 0.065],
      ],
      1,
    ),
    // upper arms: the shoulder's deltoid at the top, outermost point at x = ±0.25
    ...bothSides((s) =>
      limb('shirt', s * arm, -0.02, [
        [1.09, 0.039],
        [1.3, 0.046],
        [1.43, 0.03],
      ]),
    ),
    ...bothSides((s) =>
      limb('skin', s * arm, -0.005, [
        [0.85, 0.027],
        [1.11, 0.038],
      ]),
    ),
    ...bothSides((s) => hand(s * arm)),
  ];
}

/** Neck, head with a nose, and hair over the crown and the back of the head. */
function head(): MeshPart[] {
  const yc = (PERSON_HEAD.chin + PERSON_HEAD.crown) / 2;
  const ay = (PERSON_HEAD.crown - PERSON_HEAD.chin) / 2;
  return [
    limb('skin', 0, -0.015, [
      [1.44, 0.06],
      [1.56, 0.052],
    ]),
    ellipsoid('skin', 0, yc, 0.005, 0.0775, ay, 0.0975, 3, 2),
    ringedPart(
      'skin',
      0,
      0.098,
      [
        [1.59, 0.01, 0.014, 0.01],
        [1.64, 0.006, 0.008, 0.006, -0.006],
      ],
      1,
    ),
    ellipsoid('hair', 0, PERSON_STATURE - 0.06, -0.01, 0.082, 0.06, 0.103, 2, 1),
  ];
}

/** The person's parts, feet first. */
export function standingPersonParts(): MeshPart[] {
  return [...legs(), ...torsoAndArms(), ...head()];
}
