/**
 * The Viewer: draws the Environment's world, and attaches to a running Environment to draw it.
 *
 * <p>Drawing and transport are kept apart so that the 2D window, the 3D view and replay can reuse
 * the drawing: {@link robosim.viewer.WorldRenderer} turns a
 * {@link robosim.protocol.WorldDescription} and a {@link robosim.protocol.ViewerFrame} into an
 * image and knows nothing of sockets or files; {@link robosim.viewer.ViewerClient} speaks the
 * viewer side of the wire protocol and hands each rendered image to a
 * {@link robosim.viewer.FrameSink}, such as the {@link robosim.viewer.PngFrameWriter}.
 */
package robosim.viewer;
