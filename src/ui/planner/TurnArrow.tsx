import { headingVector } from '../../core/model/rails/geometry';

const SIZE = 24;
const C = SIZE / 2;
const STUB = 9;
const REACH = 10;

/**
 * Screen points (y down) of the picture of a chain's end and the rail an Extend button adds:
 * the end of the last rail comes in along `heading` (degrees, the model's: counterclockwise seen
 * from above, 0 = +x), the new rail leaves the joint along heading + turn. The plan is the view from
 * above with x to the right and z down (docs/planner.md), so the model's plan vector (x, z) is the
 * screen direction as it is.
 */
export function turnArrowPoints(heading: number, turn: number): { from: [number, number]; joint: [number, number]; to: [number, number]; head: [number, number][] } {
  const [ix, iz] = headingVector(heading);
  const [ox, oz] = headingVector(heading + turn);
  const to: [number, number] = [C + ox * REACH, C + oz * REACH];
  // An arrowhead of two 4 px strokes at ±150° from the new rail's direction.
  const side = (deg: number): [number, number] => {
    const [hx, hz] = headingVector(heading + turn + deg);
    return [to[0] + hx * 4, to[1] + hz * 4];
  };
  return { from: [C - ix * STUB, C - iz * STUB], joint: [C, C], to, head: [side(150), side(-150)] };
}

/**
 * The direction an "Extend the chain" button adds its rail, drawn as the plan shows it (issue 27:
 * branch buttons named by direction): the chain's last rail as a short grey line along its real heading on
 * screen, the new rail as an arrow turned by the connector's angle. Decorative: the button names it.
 */
export function TurnArrow({ heading, turn }: { heading: number; turn: number }) {
  const p = turnArrowPoints(heading, turn);
  const pt = (q: [number, number]) => `${q[0].toFixed(2)},${q[1].toFixed(2)}`;
  return (
    <svg className="turn-arrow" width={SIZE} height={SIZE} viewBox={`0 0 ${SIZE} ${SIZE}`} aria-hidden="true" focusable="false" data-heading={heading} data-turn={turn}>
      <polyline points={`${pt(p.from)} ${pt(p.joint)}`} fill="none" stroke="currentColor" strokeWidth={3} strokeLinecap="round" opacity={0.4} />
      <polyline points={`${pt(p.joint)} ${pt(p.to)}`} fill="none" stroke="currentColor" strokeWidth={2.5} strokeLinecap="round" />
      <polyline points={`${pt(p.head[0])} ${pt(p.to)} ${pt(p.head[1])}`} fill="none" stroke="currentColor" strokeWidth={2.5} strokeLinecap="round" strokeLinejoin="round" />
    </svg>
  );
}
