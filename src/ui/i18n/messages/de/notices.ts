import type { AreaMessages } from '../../messageTypes';
import type en from '../en/notices';

export default {
  shareLinkNotice: 'Link zum Teilen: {notice}',
  driverFull: 'der {capacity}-W-Treiber ist voll: {used} W belegt; wählen Sie in den Systemoptionen den {larger}-W-Treiber oder fügen Sie eine zweite Einspeisung hinzu',
  driverFullAddFeed: 'der {capacity}-W-Treiber ist voll: {used} W belegt; fügen Sie in den Systemoptionen eine zweite Einspeisung hinzu',
  feedOverload: 'Einspeisung {n} würde {load} W tragen, mehr als ihr {capacity}-W-Treiber; fügen Sie eine zweite Einspeisung hinzu oder wählen Sie einen größeren Treiber',
  driverTooSmall: 'der {capacity}-W-Treiber {driver} kann die {load} W an Einspeisung {n} nicht tragen; wählen Sie einen größeren Treiber oder fügen Sie eine Einspeisung hinzu',
  noFreeSpace: 'kein freier Platz für „{name}“ in diesem Raum',
  noRoomForModule: 'kein Platz für ein weiteres Modul {name} ({length} m) auf dieser Schiene',
  noFreeGap: 'keine freie Lücke auf dieser Schiene fasst ein Modul {name} ({length} m): die größte ist {gap} m; rücken Sie Module auseinander oder wählen Sie eine Verteilung',
  'outside-room': 'System {id} ragt aus dem Raum ({width} × {depth} m)',
  'self-overlap': 'System {id} läuft in sich selbst',
  'system-overlap': 'System {id} überschneidet System {other}',
  'suspension-range': 'die Abhängung muss zwischen {min} und {max} m liegen (war {value})',
  'suspension-floor': 'die Module würden auf {hang} m hängen, unter dem Minimum von {min} m über dem Boden',
  'rail-length-range': 'die Schienenlänge muss zwischen {min} und {max} m liegen (war {value})',
  'rail-length-grid': 'die Schienenlänge muss ein Vielfaches von {step} m sein (war {value})',
  'modules-do-not-fit': 'die Module von Schiene {rail} passen mit der Verteilung „{distribution}“ nicht auf ihre {length} m',
} satisfies AreaMessages<typeof en>;
