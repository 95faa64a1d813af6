/**
 * Offers `text` to the user as a downloaded file named `fileName`. An object URL on a temporary
 * <a download> is the standard way to start a download from script (HTML Living Standard,
 * "Downloading resources"); the anchor is attached because Firefox ignores clicks on detached
 * anchors, and the URL is revoked a little later because revoking it synchronously can cancel
 * the download before the browser has read the blob.
 */
export function downloadText(fileName: string, text: string, mimeType = 'application/json'): void {
  downloadBlob(fileName, new Blob([text], { type: mimeType }));
}

/** downloadText for any data (a zip). */
export function downloadBlob(fileName: string, blob: Blob): void {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = fileName;
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  window.setTimeout(() => URL.revokeObjectURL(url), 10_000);
}
