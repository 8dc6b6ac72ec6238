/**
 * The 3D view: walls and obstacles extruded to their heights and robots as solids, seen from a
 * camera at an azimuth and elevation with a zoom, lit from a direction with flat shading, and
 * drawn back to front (the painter's algorithm) in plain Java2D.
 *
 * <p>{@link robosim.viewer.view3d.SolidRenderer} is a {@link robosim.viewer.draw.SnapshotPainter}, so PNG
 * images, GIFs and the window draw the 3D view through it just as they draw the 2D view through
 * the {@link robosim.viewer.draw.WorldRenderer}. Pure drawing: no I/O.
 */
package robosim.viewer.view3d;
