package robosim.viewer.draw;

import java.awt.image.BufferedImage;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/**
 * Turns one snapshot into an image: the flat 2D view or the 3D view. PNG files, GIFs and the replay
 * all draw through one of these, so that they show the same picture.
 */
@FunctionalInterface
public interface SnapshotPainter {
    /**
     * @param world    the static world
     * @param snapshot the robots after one step
     * @param trails   the robots' paths so far, or {@code null}
     * @return a new image
     */
    BufferedImage paint(WorldDescription world, Snapshot snapshot, Trails trails);

    /**
     * Checks, when a world arrives and before any snapshot of it, that it can be drawn at all.
     *
     * @param world the world
     * @throws IllegalArgumentException naming the world and the rule, if it cannot be drawn
     */
    default void checkDrawable(WorldDescription world) {
        ViewTransform.fit(world, 1);
    }

    /**
     * The 2D view.
     *
     * @param renderer the renderer
     * @param options  the width and what to show
     * @return a painter drawing through the renderer with those options
     */
    static SnapshotPainter flat(WorldRenderer renderer, RenderOptions options) {
        return new SnapshotPainter() {
            @Override
            public BufferedImage paint(WorldDescription world, Snapshot snapshot, Trails trails) {
                return renderer.render(world, snapshot, options, trails);
            }

            @Override
            public void checkDrawable(WorldDescription world) {
                ViewTransform.fit(world, options.width());
            }
        };
    }
}
