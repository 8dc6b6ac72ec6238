/**
 * The Viewer's side of the wire: {@link robosim.viewer.net.ViewerClient} attaches to an Environment's
 * viewer port, says hello, and passes the world and every {@link robosim.protocol.Snapshot} to its
 * {@link robosim.protocol.recording.SnapshotListener}s (something that draws, a recorder, a window) until
 * the run ends. It draws nothing itself: drawing is {@code robosim.viewer.draw}'s.
 */
package robosim.viewer.net;
