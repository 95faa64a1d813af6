import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { ModuleInstance } from '../../core/model/configuration/configuration';
import type { Language, Translate } from '../i18n';
import { localLabel, localName } from '../i18n/localName';

/** The part of a module the note compares. */
export interface ModuleBeamState {
  id: string;
  type: string;
  beam: string;
}

/**
 * What to tell the shopper after a module changed from `before` to `module`: when its type changed
 * and the beam angle with it (the new type had no beam of that id, so beamForType took the nearest
 * angle, issue #27 "choices that stick"), which beam was set instead; else null (also when the new
 * type has no beam angles at all: a washer's default is no "nearest" beam).
 */
export function beamChangeNote(before: ModuleBeamState, module: ModuleInstance, catalog: Catalog, t: Translate, language: Language): string | null {
  if (before.id !== module.id || before.type === module.type) return null;
  const old = catalog.moduleTypes.find((m) => m.id === before.type)?.beams.find((b) => b.id === before.beam);
  const type = catalog.moduleTypes.find((m) => m.id === module.type);
  const beam = type?.beams.find((b) => b.id === module.beam);
  if (!old || !type || !beam || old.beamAngle === undefined || beam.beamAngle === undefined || beam.beamAngle === old.beamAngle) return null;
  return t('options.beamChanged', { type: localName(type, language), old: localLabel(old, language), beam: localLabel(beam, language) });
}
