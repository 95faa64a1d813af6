// The expert tools of the side panel (lazy chunks that register these English texts): the Expert switch (ExpertSwitch) and the Radiance download (RadianceButton).
export default {
  switch: 'Expert tools',
  note: 'DMX live control, Radiance download, photometric data notes',
  savedRadiance: 'Saved {name} (unpack, then sh render.sh)',
  radianceFailed: 'The Radiance export failed: {problem}',
  radianceTitle: 'A folder for the Radiance renderer: scene, luminaires, views, render.sh',
  downloadRadiance: 'Download for Radiance',
};
