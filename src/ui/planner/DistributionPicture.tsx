import type { Distribution } from '../../core/model/catalogSchema/railSystemSchema';
import { layoutModules } from '../../core/model/rails/distribution';

/** The picture's rail: 1 m with three 0.18 m modules, drawn 48 × 16 px (2 px margin at each end). */
const RAIL = 1;
const MODULE = 0.18;
const WIDTH = 48;
const HEIGHT = 16;
const MARGIN = 2;

/**
 * Where the picture draws its three modules for a distribution, in picture pixels from the left
 * edge: the model's own layout (core layoutModules) of three modules on a 1 m rail, so the picture
 * is what the choice does.
 */
export function distributionPictureOffsets(distribution: Distribution): number[] {
  const scale = (WIDTH - 2 * MARGIN) / RAIL;
  return (layoutModules([MODULE, MODULE, MODULE], RAIL, distribution) ?? []).map((o) => MARGIN + o * scale);
}

/**
 * A distribution as a small picture (issue 27, "distribution as pictures"): the rail as a line with
 * its modules as blocks where that distribution puts them. `flipped` draws the rail's start on the
 * right, for a rail that runs right to left on screen. Decorative: the button around it carries the
 * name.
 */
export function DistributionPicture({ distribution, flipped = false }: { distribution: Distribution; flipped?: boolean }) {
  // 1.5 px narrower than its share, so modules packed end to end still read as separate blocks.
  const w = MODULE * ((WIDTH - 2 * MARGIN) / RAIL) - 1.5;
  return (
    <svg className="distribution-picture" width={WIDTH} height={HEIGHT} viewBox={`0 0 ${WIDTH} ${HEIGHT}`} aria-hidden="true" focusable="false" data-distribution={distribution}>
      <g transform={flipped ? `matrix(-1 0 0 1 ${WIDTH} 0)` : undefined}>
        <rect x={MARGIN} y={7} width={WIDTH - 2 * MARGIN} height={2} rx={1} fill="currentColor" opacity={0.45} />
        {/* The rail's start: a short end cap, so start and end read apart. */}
        <rect x={0} y={4} width={2} height={8} fill="currentColor" opacity={0.45} />
        {distributionPictureOffsets(distribution).map((x, i) => (
          <rect key={i} x={x} y={3} width={w} height={10} rx={1.5} fill="currentColor" />
        ))}
      </g>
    </svg>
  );
}
