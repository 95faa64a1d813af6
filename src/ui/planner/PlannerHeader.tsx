import { useRef } from 'react';
import { LanguageSwitch } from '../i18n/LanguageSwitch';
import { BrandMark } from '../shared/BrandMark';
import type { PlannerScope } from './plannerScope';
import { useFitCompact } from './useFitCompact';

/** The planner's top bar: brand, room size, language, the total price and the side panel's toggle. */
export function PlannerHeader({ p }: { p: PlannerScope }) {
  const { ui, t, format, config, bom, panelOpen } = p;
  // The header's texts at full length where they fit, the drawer toggle as an icon where they do not.
  const headerRef = useRef<HTMLElement>(null);
  useFitCompact(headerRef);
  const toggle = t(panelOpen ? 'common.close' : 'planner.presetsToggle');
  return (
    <header ref={headerRef} className="app-header">
      <BrandMark ui={ui} />
      <span className="room-label">{t('planner.roomSize', { width: config.room.width, depth: config.room.depth, height: config.room.height })}</span>
      <span className="spacer" />
      {p.languageSwitch && <LanguageSwitch />}
      <span className="total" data-testid="header-total" aria-label={t('planner.totalPrice')}>
        {format.money(bom.total, bom.currency)}
      </span>
      <button type="button" className="btn panel-toggle" aria-expanded={panelOpen} aria-label={toggle} title={toggle} data-testid="panel-toggle" onClick={() => ui.setState({ panelOpen: !panelOpen })}>
        <span className="toggle-text">{toggle}</span>
      </button>
    </header>
  );
}
