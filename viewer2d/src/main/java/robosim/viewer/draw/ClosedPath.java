package robosim.viewer.draw;

import java.awt.geom.Path2D;
import java.util.function.IntToDoubleFunction;

/**
 * Builds a polygon's closed outline in pixels, in any view (the 2D plan, the 3D projection): the
 * caller says where each corner lands on the screen.
 */
public final class ClosedPath {
    private ClosedPath() {
    }

    /**
     * @param corners how many corners the polygon has
     * @param x       the screen x of corner {@code i}
     * @param y       the screen y of corner {@code i}
     * @return the outline from corner 0 through each corner in turn, closed back to corner 0
     */
    public static Path2D of(int corners, IntToDoubleFunction x, IntToDoubleFunction y) {
        Path2D.Double path = new Path2D.Double();
        for (int i = 0; i < corners; i++) {
            if (i == 0) {
                path.moveTo(x.applyAsDouble(i), y.applyAsDouble(i));
            } else {
                path.lineTo(x.applyAsDouble(i), y.applyAsDouble(i));
            }
        }
        path.closePath();
        return path;
    }
}
