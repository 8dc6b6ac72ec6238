package robosim.env.sensors;

import java.util.List;
import robosim.geometry.Pose2D;
import robosim.protocol.SonarUnit;

/**
 * A sonar ring's cones at the robot's pose: each transducer's apex in the world and the unit
 * vectors along its cone's two edges. The edges depend on the heading alone, so a robot that has
 * not turned since its previous reading (standing, or driving straight) keeps them: the same
 * heading gives the same vectors, bit for bit, and the ring's sines and cosines (four per
 * transducer, and the heading's own two) are worked out only when it turns.
 */
final class SonarCones {
    private final int[] index;
    private final double[] localX;
    private final double[] localY;
    /** Each transducer's heading on the body, radians. */
    private final double[] heading;
    private final double halfAngle;
    /** Per transducer: the right edge's x and y, then the left edge's. */
    private final double[] edges;
    private final double[] apexX;
    private final double[] apexY;
    /** The heading the edges are for, as {@link Double#doubleToRawLongBits}; none at first. */
    private long aimedBits;
    private boolean aimed;
    private double cos;
    private double sin;

    /**
     * @param units     the ring's transducers, in the parameter file's order
     * @param halfAngle half of every cone's opening, radians
     */
    SonarCones(List<SonarUnit> units, double halfAngle) {
        int n = units.size();
        index = new int[n];
        localX = new double[n];
        localY = new double[n];
        heading = new double[n];
        for (int k = 0; k < n; k++) {
            SonarUnit s = units.get(k);
            index[k] = s.index();
            localX[k] = s.x();
            localY[k] = s.y();
            heading[k] = Math.toRadians(s.th());
        }
        this.halfAngle = halfAngle;
        edges = new double[4 * n];
        apexX = new double[n];
        apexY = new double[n];
    }

    /** @return how many transducers */
    int size() {
        return index.length;
    }

    /**
     * Places the cones at a pose: the apexes as {@link Pose2D#worldX} and {@link Pose2D#worldY}
     * place them, the edges as {@code Surroundings.cone} turns the axis {@code th + heading} by
     * the half angle each way.
     *
     * @param p the robot's true pose
     */
    void aim(Pose2D p) {
        long bits = Double.doubleToRawLongBits(p.th());
        if (!aimed || bits != aimedBits) {
            cos = Math.cos(p.th());
            sin = Math.sin(p.th());
            for (int k = 0; k < index.length; k++) {
                double axis = p.th() + heading[k];
                edges[4 * k] = Math.cos(axis - halfAngle);
                edges[4 * k + 1] = Math.sin(axis - halfAngle);
                edges[4 * k + 2] = Math.cos(axis + halfAngle);
                edges[4 * k + 3] = Math.sin(axis + halfAngle);
            }
            aimedBits = bits;
            aimed = true;
        }
        for (int k = 0; k < index.length; k++) {
            apexX[k] = p.x() + localX[k] * cos - localY[k] * sin;
            apexY[k] = p.y() + localX[k] * sin + localY[k] * cos;
        }
    }

    /** @return transducer k's number, its bit in a firing and its place in the readings */
    int index(int k) {
        return index[k];
    }

    double apexX(int k) {
        return apexX[k];
    }

    double apexY(int k) {
        return apexY[k];
    }

    /** @return the x of the unit vector along transducer k's right edge */
    double rightX(int k) {
        return edges[4 * k];
    }

    double rightY(int k) {
        return edges[4 * k + 1];
    }

    double leftX(int k) {
        return edges[4 * k + 2];
    }

    double leftY(int k) {
        return edges[4 * k + 3];
    }
}
