import type { AreaMessages } from '../../messageTypes';
import type en from '../en/notices';

export default {
  shareLinkNotice: 'Link zum Teilen: {notice}',
  driverFull: 'der {capacity}-W-Treiber ist voll: {used} W belegt; fügen Sie eine zweite Einspeisung hinzu oder wählen Sie einen größeren Treiber',
  feedOverload: 'Einspeisung {n} würde {load} W tragen, mehr als ihr {capacity}-W-Treiber; fügen Sie eine zweite Einspeisung hinzu oder wählen Sie einen größeren Treiber',
  driverTooSmall: 'der {capacity}-W-Treiber {driver} kann die {load} W an Einspeisung {n} nicht tragen; wählen Sie einen größeren Treiber oder fügen Sie eine Einspeisung hinzu',
  noFreeSpace: 'kein freier Platz für „{name}“ in diesem Raum',
  noRoomForModule: 'kein Platz für ein weiteres Modul {name} ({length} m) auf dieser Schiene',
  noFreeGap: 'keine freie Lücke auf dieser Schiene fasst ein Modul {name} ({length} m): die größte ist {gap} m; rücken Sie Module auseinander oder wählen Sie eine Verteilung',
} satisfies AreaMessages<typeof en>;
