/**
 * Drawing a run, with no transport in it: {@link robosim.viewer.draw.WorldRenderer} turns a
 * {@link robosim.protocol.WorldDescription} and a {@link robosim.protocol.Snapshot} (and the robots'
 * {@link robosim.viewer.draw.Trails}) into an image; {@link robosim.viewer.draw.RenderedImages} follows a
 * run as a {@link robosim.protocol.recording.SnapshotListener} and hands images, drawn by a
 * {@link robosim.viewer.draw.SnapshotPainter} (this flat view, or the 3D view of
 * {@code robosim.viewer.view3d}), to an {@link robosim.viewer.draw.ImageSink} such as the
 * {@link robosim.viewer.draw.PngImageWriter}. PNG images of a live run (a
 * {@code RenderedImages} among the listeners of {@code robosim.viewer.net}'s client), the window
 * ({@code robosim.viewer.window}) and replay ({@code robosim.viewer.replay}) all draw through these,
 * so they show the same pictures.
 */
package robosim.viewer.draw;
