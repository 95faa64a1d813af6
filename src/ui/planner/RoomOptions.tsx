import type { Room } from '../../core/model/configuration';
import type { ActionGate } from './actionGate';
import { CommitField } from './CommitField';
import { OptionsSection } from './OptionsSection';

const DIMENSIONS = [
  { key: 'width', title: 'Width (m)', label: 'Room width (m)' },
  { key: 'depth', title: 'Depth (m)', label: 'Room depth (m)' },
  { key: 'height', title: 'Height (m)', label: 'Room height (m)' },
] as const;

/** With nothing selected, the options are the room's: width, depth and height, each one setRoom. */
export function RoomOptions({ room, gate, onClose }: { room: Room; gate: ActionGate; onClose: () => void }) {
  const size = { width: room.width, depth: room.depth, height: room.height };
  return (
    <OptionsSection title="Room" onClose={onClose}>
      <div className="setup-fields">
        {DIMENSIONS.map((d) => (
          <div className="field" key={d.key}>
            <h3>{d.title}</h3>
            <CommitField label={d.label} value={size[d.key]} onCommit={(v) => gate.attempt('setRoom', { ...size, [d.key]: v })} onRefused={gate.explain} />
          </div>
        ))}
      </div>
    </OptionsSection>
  );
}
