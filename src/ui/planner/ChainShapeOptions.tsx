import type { Catalog } from '../../core/model/catalogSchema';
import type { LightSystem } from '../../core/model/configuration';
import { suspensionCoordinates } from '../../core/model/suspensionPoints';
import type { ActionGate } from './actionGate';
import { CommitField } from './CommitField';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';

/**
 * A selected system's adjustable shape (docs/planner.md, "Connector angles and fixing points"):
 * the turn of every flexible-angle connector (a number field plus steps of the catalog's grid and
 * straight), and every fixing point's position along the chain (a field per point; a point on a
 * connector is fixed there). Every control is gated by the model: a refused value snaps back and
 * the model's reason is shown; disabled buttons carry it as their title.
 */
export function ChainShapeOptions({ system, catalog, gate }: { system: LightSystem; catalog: Catalog; gate: ActionGate }) {
  const systemId = system.id;
  const flexJoints = system.joints.flatMap((j, k) => {
    const con = catalog.connectors.find((c) => c.id === j.connector);
    return con?.flex ? [{ joint: k, turn: j.turn, con, step: con.flex.step, max: con.flex.maxAngle }] : [];
  });
  const points = suspensionCoordinates(system, catalog);
  const what = system.mounting === 'surface' ? 'Clip' : 'Suspension';
  return (
    <>
      {flexJoints.map(({ joint, turn, con, step, max }) => (
        <div className="field" key={joint} data-testid={`joint-angle-${joint}`}>
          <h3>
            Connector {joint + 1} angle (°, left +)
          </h3>
          <CommitField label={`Connector ${joint + 1} angle (°)`} value={turn} decimals={0} onCommit={(degrees) => gate.attempt('setJointTurn', { systemId, joint, degrees })} onRefused={gate.explain} testId={`joint-angle-field-${joint}`} />
          <OptionChips title={`Connector ${joint + 1} angle`}>
            <GatedButton gate={gate} action="setJointTurn" params={{ systemId, joint, degrees: turn + step }} label={`Turn connector ${joint + 1} left ${step}°`} testId={`joint-left-${joint}`}>
              ↰ {step}°
            </GatedButton>
            <GatedButton gate={gate} action="setJointTurn" params={{ systemId, joint, degrees: 0 }} label={`Connector ${joint + 1} straight`} current={turn === 0} testId={`joint-straight-${joint}`}>
              0°
            </GatedButton>
            <GatedButton gate={gate} action="setJointTurn" params={{ systemId, joint, degrees: turn - step }} label={`Turn connector ${joint + 1} right ${step}°`} testId={`joint-right-${joint}`}>
              ↱ {step}°
            </GatedButton>
          </OptionChips>
          <span className="empty-note">
            {con.name}: ±{max}° in steps of {step}°
          </span>
        </div>
      ))}
      <div className="field" data-testid="fixing-points">
        <h3>{what} points along the chain (m)</h3>
        {points.map((p, index) => (
          <p key={index} className="fixing-point" data-testid={`fixing-${index}`}>
            {what} {index + 1}:{' '}
            {p.joint !== null ? (
              <span className="preset-detail">
                {p.s.toFixed(2)} m, at connector {p.joint + 1} (a connector is always a support)
              </span>
            ) : (
              <CommitField label={`${what} ${index + 1} position (m)`} value={p.s} onCommit={(s) => gate.attempt('moveFixingPoint', { systemId, index, s })} onRefused={gate.explain} testId={`fixing-field-${index}`} />
            )}
          </p>
        ))}
        <span className="empty-note">
          {system.fixings ? 'moved by hand; a change to the chain that breaks the rules puts them back' : 'placed by the rules'}: at most{' '}
          {system.mounting === 'surface' ? catalog.surfaceMount.spacing : catalog.suspension.maxSpacing} m apart, ends overhang at most{' '}
          {system.mounting === 'surface' ? catalog.surfaceMount.maxOverhang : catalog.suspension.maxOverhang} m
        </span>
      </div>
    </>
  );
}
