// Names of the furnished room presets, by id.
export default {
  'living-room': 'Living room',
  'dining-room': 'Dining room',
  'shop-window': 'Shop window',
};
