/**
 * The Viewer: draws the Environment's world, and attaches to a running Environment to draw it.
 *
 * <p>Drawing and transport are kept apart so that the window, the 3D view and replay reuse the
 * drawing: {@link robosim.viewer.WorldRenderer} turns a {@link robosim.protocol.WorldDescription}
 * and a {@link robosim.protocol.Snapshot} (and the robots' {@link robosim.viewer.Trails}) into
 * an image and knows nothing of sockets or files. {@link robosim.viewer.ViewerClient} speaks the
 * viewer side of the wire protocol and passes the run to
 * {@link robosim.protocol.recording.SnapshotListener}s: a {@link robosim.viewer.RenderedImages}
 * draws snapshots through a {@link robosim.viewer.SnapshotPainter} (2D, or the 3D view of
 * {@code robosim.viewer.view3d}) into a {@link robosim.viewer.ImageSink} such as the
 * {@link robosim.viewer.PngImageWriter}; a recording writer records; the window of
 * {@code robosim.viewer.window} shows. {@code robosim.viewer.replay} feeds a recording to the
 * same listeners without an Environment, so live and replayed snapshots are drawn alike.
 */
package robosim.viewer;
