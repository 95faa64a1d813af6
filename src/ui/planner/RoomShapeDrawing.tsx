import type { RoomShape } from '../../core/model/configuration/configuration';
import { doubleSignedArea, type PlanPoint } from '../../core/room/planPolygon';

/** Wall i's corners, unit direction and unit normal into the room (the outline may run either way). */
export function shapeWall(outline: readonly PlanPoint[], i: number) {
  const a = outline[i];
  const b = outline[(i + 1) % outline.length];
  const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
  const u: PlanPoint = [(b[0] - a[0]) / length, (b[1] - a[1]) / length];
  const s = doubleSignedArea(outline) >= 0 ? 1 : -1;
  const n: PlanPoint = [-s * u[1], s * u[0]];
  return { a, b, length, u, n };
}

const at = (p: PlanPoint, u: PlanPoint, t: number, n: PlanPoint = [0, 0], s = 0) => `${p[0] + u[0] * t + n[0] * s},${p[1] + u[1] * t + n[1] * s}`;
/** Far enough to reach past any room (500 m is the largest coordinate, roomInput.ts). */
const FAR = 1000;

/**
 * A drawn room in the plan (issue 29, docs/planner.md "Rooms of any shape"): walls as thick
 * lines broken where the openings are, a door's leaf and swing, a window's glass line, and each
 * slope as a hatched band from its wall to where it meets the flat ceiling (dashed), clipped to
 * the floor. Drawn in metres inside the plan's view group; a chunk of its own (LazyRoomShapeDrawing),
 * fetched only for a room that has a shape, so the box's first screen does not carry it.
 */
export default function RoomShapeDrawing({ shape, height, clipId, hatchId }: { shape: RoomShape; height: number; clipId: string; hatchId: string }) {
  const { outline } = shape;
  return (
    <g pointerEvents="none">
      <defs>
        <pattern id={hatchId} patternUnits="userSpaceOnUse" width={0.15} height={0.15} patternTransform="rotate(45)">
          <line x1={0} y1={0} x2={0} y2={0.15} stroke="#8a6d3b" strokeWidth={0.025} />
        </pattern>
      </defs>
      <g clipPath={`url(#${clipId})`}>
        {shape.slopes.map((slope) => {
          const { a, u, n } = shapeWall(outline, slope.wall);
          // Where the slope reaches the flat ceiling: knee + tan(pitch)·d = height.
          const d = (height - slope.kneeHeight) / Math.tan((slope.pitch * Math.PI) / 180);
          return (
            <g key={slope.wall} data-slope-wall={slope.wall}>
              <path d={`M${at(a, u, -FAR, n, -FAR)}L${at(a, u, FAR, n, -FAR)}L${at(a, u, FAR, n, d)}L${at(a, u, -FAR, n, d)}Z`} fill={`url(#${hatchId})`} fillOpacity={0.6} />
              <line
                x1={a[0] + n[0] * d - u[0] * FAR}
                y1={a[1] + n[1] * d - u[1] * FAR}
                x2={a[0] + n[0] * d + u[0] * FAR}
                y2={a[1] + n[1] * d + u[1] * FAR}
                stroke="#8a6d3b"
                strokeWidth={1.5}
                strokeDasharray="6 4"
                vectorEffect="non-scaling-stroke"
              />
            </g>
          );
        })}
      </g>
      <g data-testid="plan-walls">
        {outline.map((_, i) => {
          const { a, length, u } = shapeWall(outline, i);
          const gaps = shape.openings.filter((o) => o.wall === i).sort((x, y) => x.offset - y.offset);
          let from = 0;
          const parts: string[] = [];
          for (const o of gaps) {
            parts.push(`M${at(a, u, from)}L${at(a, u, o.offset)}`);
            from = o.offset + o.width;
          }
          parts.push(`M${at(a, u, from)}L${at(a, u, length)}`);
          return <path key={i} d={parts.join('')} fill="none" stroke="#1d2330" strokeWidth={3} strokeLinecap="square" vectorEffect="non-scaling-stroke" />;
        })}
      </g>
      {shape.openings.map((o, k) => {
        const { a, u, n } = shapeWall(outline, o.wall);
        const hinge = at(a, u, o.offset);
        const paint = { fill: 'none', strokeWidth: 1.5, vectorEffect: 'non-scaling-stroke' as const };
        // The leaf open at 90° into the room, and its swing from the closed position: SVG's positive sweep turns +x toward +z.
        const sweep = u[0] * n[1] - u[1] * n[0] > 0 ? 1 : 0;
        return (
          <g key={k} data-opening-kind={o.kind} data-opening-wall={o.wall}>
            {o.kind === 'door' ? (
              <path d={`M${hinge}L${at(a, u, o.offset, n, o.width)}M${at(a, u, o.offset + o.width)}A${o.width},${o.width} 0 0 ${sweep} ${at(a, u, o.offset, n, o.width)}`} stroke="#4a5160" {...paint} />
            ) : o.kind === 'window' ? (
              <path d={`M${hinge}L${at(a, u, o.offset + o.width)}`} stroke="#3b7be0" {...paint} strokeWidth={3} strokeDasharray="2 2" />
            ) : (
              <path d={`M${at(a, u, o.offset, n, -0.08)}L${at(a, u, o.offset, n, 0.08)}M${at(a, u, o.offset + o.width, n, -0.08)}L${at(a, u, o.offset + o.width, n, 0.08)}`} stroke="#1d2330" {...paint} />
            )}
          </g>
        );
      })}
    </g>
  );
}
