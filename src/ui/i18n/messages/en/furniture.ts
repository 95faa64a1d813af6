// Names of the furniture library's items, by item id.
export default {
  'dining-table': 'Dining table',
  'coffee-table': 'Coffee table',
  chair: 'Chair',
  sofa: 'Sofa (three seats)',
  armchair: 'Armchair',
  sideboard: 'Sideboard',
  'open-shelf': 'Open shelf with books',
  bed: 'Double bed',
  desk: 'Desk',
  'kitchen-island': 'Kitchen island',
  picture: 'Framed picture',
  'floor-plant': 'Floor plant',
  person: 'Standing person',
};
