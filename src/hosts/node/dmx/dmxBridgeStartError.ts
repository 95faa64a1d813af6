/** A socket could not be opened (port in use, address not local): bad input, not a bug. */
export class DmxBridgeStartError extends Error {
  override name = 'DmxBridgeStartError';
}
