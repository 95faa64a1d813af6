// The package's door for pages without a bundler, `luxbox/element` (docs/package.md): importing it
// registers `<luxbox-configurator>` (the one side effect of the package, package.json sideEffects).
import { LuxboxConfiguratorElement } from './LuxboxConfiguratorElement';

export { LuxboxConfiguratorElement, parseRoomAttribute, type LuxboxElementEventMap } from './LuxboxConfiguratorElement';
export type { LuxboxInstance, LuxboxOptions } from '../embed/types';
export type { BillOfMaterials } from '../../core/model/power/billOfMaterials';

if (typeof customElements !== 'undefined' && !customElements.get('luxbox-configurator')) customElements.define('luxbox-configurator', LuxboxConfiguratorElement);
