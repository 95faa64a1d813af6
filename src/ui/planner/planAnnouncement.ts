import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Selection } from '../../core/store/createConfiguratorStore';
import type { Format } from '../i18n/createFormat';
import type { Language } from '../i18n/languages';
import { localLabel, localName } from '../i18n/localName';
import type { Translate } from '../i18n/messageTypes';
import '../i18n/registerA11yEnglish';

/** What the announcer compares between two states of the configurator store. */
export interface AnnouncedState {
  config: Configuration;
  selection: Selection;
  /** Undo steps available (history.past.length) and redo steps (history.future.length). */
  past: number;
  future: number;
}

export interface AnnounceContext {
  catalog: Catalog;
  t: Translate;
  format: Format;
  language: Language;
}

/**
 * The selected item in words, as a sighted user reads it off the plan: which module of which
 * rail (and system, when there are several), its type, beam, colour temperature and level; a
 * rail with its length and modules; a system with its rails and modules. null: nothing selected
 * (or the selection no longer exists).
 */
export function describeSelection(config: Configuration, selection: Selection, c: AnnounceContext): string | null {
  if (!selection) return null;
  const { t, format, catalog, language } = c;
  if (selection.kind === 'object') {
    const index = config.objects.findIndex((o) => o.id === selection.id);
    return index < 0 ? null : t('a11y.object', { index: index + 1 });
  }
  const several = config.systems.length > 1;
  for (const [si, s] of config.systems.entries()) {
    const system = si + 1;
    const modules = s.rails.reduce((n, r) => n + r.modules.length, 0);
    if (selection.kind === 'system' && s.id === selection.id) {
      return [t('a11y.system', { system }), t('a11y.railCount', { count: s.rails.length }), t('a11y.moduleCount', { count: modules })].join(', ');
    }
    for (const [ri, r] of s.rails.entries()) {
      const rail = ri + 1;
      if (selection.kind === 'rail' && r.id === selection.id) {
        return [t('a11y.rail', { rail, system, length: format.metres(r.length) }), t('a11y.moduleCount', { count: r.modules.length })].join(', ');
      }
      const mi = selection.kind === 'module' ? r.modules.findIndex((m) => m.id === selection.id) : -1;
      if (mi < 0) continue;
      const m = r.modules[mi];
      const where = { index: mi + 1, count: r.modules.length, rail, system };
      const type = catalog.moduleTypes.find((x) => x.id === m.type);
      const beam = type?.beams.find((b) => b.id === m.beam);
      const off = m.on === false || m.dimming === 0;
      return [
        t(several ? 'a11y.moduleInSystem' : 'a11y.module', where),
        type ? localName(type, language) : m.type,
        ...(beam && type && type.beams.length > 1 ? [localLabel(beam, language)] : []),
        `${format.number(m.cct, { useGrouping: false })} K`,
        off ? t('a11y.moduleOff') : format.percent(m.dimming),
      ].join(', ');
    }
  }
  return null;
}

function roomSummary(config: Configuration, c: AnnounceContext): string {
  const modules = config.systems.reduce((n, s) => n + s.rails.reduce((k, r) => k + r.modules.length, 0), 0);
  return c.t('a11y.room', {
    systems: c.t('a11y.systemCount', { count: config.systems.length }),
    modules: c.t('a11y.moduleCount', { count: modules }),
    objects: c.t('a11y.objectCount', { count: config.objects.length }),
  });
}

/**
 * What a screen reader should hear after the store went from `prev` to `next` (null: nothing
 * worth saying). A new selection is announced as "… selected"; a change to the configuration
 * repeats the selected item with its new state ("Changed: Module 2 of 3 on rail 1, Spot, wide,
 * 3000 K, 50 %"), or, with nothing selected, what the room now holds; undo and redo say so first.
 */
export function announcement(prev: AnnouncedState, next: AnnouncedState, c: AnnounceContext): string | null {
  const selectionChanged = prev.selection?.kind !== next.selection?.kind || prev.selection?.id !== next.selection?.id;
  const configChanged = prev.config !== next.config;
  if (!selectionChanged && !configChanged) return null;
  const what = describeSelection(next.config, next.selection, c);
  if (configChanged) {
    const state = what ?? roomSummary(next.config, c);
    if (next.past < prev.past && next.future > prev.future) return c.t('a11y.undone', { what: state });
    if (next.future < prev.future && next.past > prev.past) return c.t('a11y.redone', { what: state });
    if (selectionChanged) return what ? c.t('a11y.selected', { what }) : state;
    return what ? c.t('a11y.changed', { what }) : state;
  }
  return what ? c.t('a11y.selected', { what }) : c.t('a11y.cleared');
}
