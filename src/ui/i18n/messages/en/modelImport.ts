// The import preview's summary of how the model was oriented (ImportPreview, a lazy chunk that registers these English texts).
export default {
  orientTurned: { one: '{count} closed part faced inward and was turned outward', other: '{count} closed parts faced inward and were turned outward' },
  orientTwoSided: { one: '{count} open surface is lit and reflects on both sides', other: '{count} open surfaces are lit and reflect on both sides' },
  orientOneSided: { one: '{count} open surface is lit from its front only (one-sided in the file)', other: '{count} open surfaces are lit from their front only (one-sided in the file)' },
  orientUndecided: { one: '{count} part has no clear inside (faces that cannot be wound alike): it is lit on both sides', other: '{count} parts have no clear inside (faces that cannot be wound alike): they are lit on both sides' },
  orientClosed: 'Every part is closed and faces outward',
};
