import type en from '../en/daylightPlan';
import type { AreaMessages } from '../../messageTypes';

export default {
  toggle: 'Tageslichtquotient',
  hint: 'Tageslichtquotient auf der Nutzebene bei bedecktem Himmel: Beleuchtungsstärke innen ÷ außen',
  computing: 'Wird berechnet…',
  noSky: 'Zu dieser Zeit steht die Sonne unter dem Horizont: Wählen Sie eine Tageszeit mit Tageslicht.',
  unavailable: 'Der Tageslichtquotient braucht 3D-Grafik (WebGL 2), die dieser Browser nicht bietet.',
  band: 'Leer: 0,5 m entlang der Wände (EN 17037).',
} satisfies AreaMessages<typeof en>;
