/**
 * Replay without an Environment: render a recording's snapshots to PNG files or an animated GIF
 * through the same {@link robosim.viewer.draw.SnapshotPainter}s the live viewer uses, and sum a recording
 * up (distance travelled, collisions) from its true poses.
 */
package robosim.viewer.replay;
