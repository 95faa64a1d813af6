import './registerOptionsEnglish';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { ActionGate } from './actionGate';
import type { FootprintSource } from './footprintSource';
import { ModuleOptions } from './ModuleOptions';
import type { AimAtMode } from '../shared/aimAtMode';
import { ObjectOptions } from './ObjectOptions';
import { RailOptions } from './RailOptions';
import { RoomOptions } from './RoomOptions';
import type { SelectionPath } from './selection';
import { SystemOptions } from './SystemOptions';

export interface OptionsPanelProps {
  config: Configuration;
  catalog: Catalog;
  path: SelectionPath;
  gate: ActionGate;
  onClose: () => void;
  /** The plan's photometry loader: a selected module's file warnings are shown from it. */
  footprints?: FootprintSource;
  /** Aim-at mode shared with the 3D view (docs/aiming.md). */
  aimMode?: AimAtMode;
}

/**
 * Settings of the selected part (configurator paper, fig. 10, 11), the deepest selected: an
 * object, a module, a rail, a system, or with nothing selected the room. Every choice is gated by the model.
 */
export function OptionsPanel({ config, catalog, path, gate, onClose, footprints, aimMode }: OptionsPanelProps) {
  const object = config.objects.find((o) => o.id === path.objectId);
  if (object) return <ObjectOptions config={config} object={object} gate={gate} onClose={onClose} />;
  const system = config.systems.find((s) => s.id === path.systemId);
  const rail = system?.rails.find((r) => r.id === path.railId);
  const module = rail?.modules.find((m) => m.id === path.moduleId);
  if (module) return <ModuleOptions module={module} catalog={catalog} gate={gate} onClose={onClose} footprints={footprints} aimMode={aimMode} />;
  if (rail && system) return <RailOptions rail={rail} system={system} catalog={catalog} gate={gate} onClose={onClose} />;
  if (system) return <SystemOptions system={system} catalog={catalog} gate={gate} onClose={onClose} />;
  return <RoomOptions room={config.room} gate={gate} onClose={onClose} />;
}
