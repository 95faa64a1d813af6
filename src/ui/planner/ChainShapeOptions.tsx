import './registerOptionsEnglish';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { LightSystem } from '../../core/model/configuration/configuration';
import { suspensionCoordinates } from '../../core/model/rails/suspensionPoints';
import type { ActionGate } from './actionGate';
import { CommitField } from '../shared/CommitField';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { useI18n } from '../i18n/useI18n';

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
  const { t, format } = useI18n();
  const points = suspensionCoordinates(system, catalog);
  const surface = system.mounting === 'surface';
  return (
    <>
      {flexJoints.map(({ joint, turn, con, step, max }) => (
        <div className="field" key={joint} data-testid={`joint-angle-${joint}`}>
          <h3>{t('options.connectorAngleHeading', { n: joint + 1 })}</h3>
          <CommitField
            label={t('options.connectorAngleField', { n: joint + 1 })}
            value={turn}
            decimals={0}
            onCommit={(degrees) => gate.attempt('setJointTurn', { systemId, joint, degrees })}
            onRefused={gate.explain}
            testId={`joint-angle-field-${joint}`}
          />
          <OptionChips title={t('options.connectorAngle', { n: joint + 1 })}>
            <GatedButton gate={gate} action="setJointTurn" params={{ systemId, joint, degrees: turn + step }} label={t('options.turnConnectorLeft', { n: joint + 1, step })} testId={`joint-left-${joint}`}>
              ↰ {step}°
            </GatedButton>
            <GatedButton gate={gate} action="setJointTurn" params={{ systemId, joint, degrees: 0 }} label={t('options.connectorStraight', { n: joint + 1 })} current={turn === 0} testId={`joint-straight-${joint}`}>
              0°
            </GatedButton>
            <GatedButton gate={gate} action="setJointTurn" params={{ systemId, joint, degrees: turn - step }} label={t('options.turnConnectorRight', { n: joint + 1, step })} testId={`joint-right-${joint}`}>
              ↱ {step}°
            </GatedButton>
          </OptionChips>
          <span className="empty-note">{t('options.connectorRange', { name: con.name, max, step })}</span>
        </div>
      ))}
      <div className="field" data-testid="fixing-points">
        <h3>{t(surface ? 'options.clipPointsHeading' : 'options.suspensionPointsHeading')}</h3>
        {points.map((p, index) => (
          <p key={index} className="fixing-point" data-testid={`fixing-${index}`}>
            {t(surface ? 'options.clipN' : 'options.suspensionN', { n: index + 1 })}{' '}
            {p.joint !== null ? (
              <span className="preset-detail">{t('options.fixingAtConnector', { position: format.metres(p.s), n: p.joint + 1 })}</span>
            ) : (
              <CommitField
                label={t(surface ? 'options.clipPosition' : 'options.suspensionPosition', { n: index + 1 })}
                value={p.s}
                onCommit={(s) => gate.attempt('moveFixingPoint', { systemId, index, s })}
                onRefused={gate.explain}
                testId={`fixing-field-${index}`}
              />
            )}
          </p>
        ))}
        <span className="empty-note">
          {t(system.fixings ? 'options.fixingsByHand' : 'options.fixingsByRules', {
            spacing: surface ? catalog.surfaceMount.spacing : catalog.suspension.maxSpacing,
            overhang: surface ? catalog.surfaceMount.maxOverhang : catalog.suspension.maxOverhang,
          })}
        </span>
      </div>
    </>
  );
}
