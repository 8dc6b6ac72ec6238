package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.List;

/**
 * The line a Gold robot drives along its committed cells, without stopping between them: in each
 * cell a piece from the middle of the side it comes in by to the middle of the side it leaves by,
 * straight through the centre, or, where the way turns, a quarter circle of half a cell's radius
 * about the cell's corner between those sides. The pieces meet at the sides' middles square to
 * the side, so the line has no kink; it ends at the last cell's centre, where the robot stops. A
 * robot that stands (it has just started, or stopped) starts where it is, on a straight piece.
 *
 * <p>A track is made again each step from the robot's {@link Course} and pose; it tells the
 * driving how far the robot has to the stop and to the next bend, and where the line lies ahead.
 */
final class Track {
    /** One piece: a segment, or an arc about a centre. */
    private record Piece(boolean arc, double x0, double y0, double x1, double y1, double cx, double cy, double a0,
                         double sweep, double length) {
        static Piece line(double x0, double y0, double x1, double y1) {
            return new Piece(false, x0, y0, x1, y1, 0, 0, 0, 0, Math.hypot(x1 - x0, y1 - y0));
        }

        /** The point {@code s} mm along the piece. */
        double[] at(double s, double radius) {
            if (arc) {
                double a = a0 + Math.signum(sweep) * s / radius;
                return new double[] {cx + radius * Math.cos(a), cy + radius * Math.sin(a)};
            }
            double f = length == 0 ? 0 : s / length;
            return new double[] {x0 + f * (x1 - x0), y0 + f * (y1 - y0)};
        }

        /** How far along the piece the point nearest (px, py) lies, 0 to its length. */
        double project(double px, double py, double radius) {
            if (arc) {
                double a = Math.atan2(py - cy, px - cx) - a0;
                a = Math.atan2(Math.sin(a), Math.cos(a)) * Math.signum(sweep);
                return Math.max(0, Math.min(length, a * radius));
            }
            if (length == 0) {
                return 0;
            }
            double f = ((px - x0) * (x1 - x0) + (py - y0) * (y1 - y0)) / (length * length);
            return Math.max(0, Math.min(length, f * length));
        }
    }

    private final List<Piece> pieces = new ArrayList<>();
    private final double radius;
    /** How far along the first piece the robot is. */
    private final double progress;

    /**
     * The track of a course, for a robot at (px, py).
     *
     * @param course   its cell, the side it came in by, and its committed cells
     * @param cellSize the maze's cell size, mm
     * @param px       the robot's position, mm
     * @param py       mm
     */
    Track(Course course, double cellSize, double px, double py) {
        this.radius = cellSize / 2;
        List<Long> cells = new ArrayList<>();
        cells.add(course.here());
        cells.addAll(course.ahead());
        int entry = course.entry();
        for (int i = 0; i < cells.size(); i++) {
            long cell = cells.get(i);
            int exit = i + 1 < cells.size() ? sideTowards(cell, cells.get(i + 1)) : -1;
            double cx = (MazeKnowledge.keyX(cell) + 0.5) * cellSize;
            double cy = (MazeKnowledge.keyY(cell) + 0.5) * cellSize;
            double[] in = i == 0 && entry < 0 ? new double[] {px, py} : middle(cx, cy, entry);
            if (exit < 0) {
                pieces.add(Piece.line(in[0], in[1], cx, cy));
            } else if (entry < 0 || exit == (entry + 2) % 4) {
                double[] out = middle(cx, cy, exit);
                pieces.add(Piece.line(in[0], in[1], out[0], out[1]));
            } else {
                pieces.add(arc(cx, cy, entry, exit));
            }
            entry = (exit + 2) % 4;
        }
        this.progress = pieces.get(0).project(px, py, radius);
    }

    /** The side of cell {@code from} that leads into the neighbouring cell {@code to}. */
    static int sideTowards(long from, long to) {
        int dx = MazeKnowledge.keyX(to) - MazeKnowledge.keyX(from);
        int dy = MazeKnowledge.keyY(to) - MazeKnowledge.keyY(from);
        for (int d = 0; d < 4; d++) {
            if (Directions.dx(d) == dx && Directions.dy(d) == dy) {
                return d;
            }
        }
        throw new IllegalArgumentException("cells " + MazeKnowledge.keyX(from) + "," + MazeKnowledge.keyY(from)
                + " and " + MazeKnowledge.keyX(to) + "," + MazeKnowledge.keyY(to) + " are not neighbours");
    }

    /** The middle of side {@code d} of the cell centred at (cx, cy). */
    private double[] middle(double cx, double cy, int d) {
        return new double[] {cx + Directions.dx(d) * radius, cy + Directions.dy(d) * radius};
    }

    /** The quarter circle about the corner between the side it comes in by and the side it leaves by. */
    private Piece arc(double cx, double cy, int entry, int exit) {
        double ox = cx + (Directions.dx(entry) + Directions.dx(exit)) * radius;
        double oy = cy + (Directions.dy(entry) + Directions.dy(exit)) * radius;
        double a0 = Math.atan2(-Directions.dy(exit), -Directions.dx(exit));
        double a1 = Math.atan2(-Directions.dy(entry), -Directions.dx(entry));
        double sweep = Math.atan2(Math.sin(a1 - a0), Math.cos(a1 - a0));
        return new Piece(true, 0, 0, 0, 0, ox, oy, a0, sweep, Math.abs(sweep) * radius);
    }

    /** @return the way left to the track's end, where the robot stops, mm */
    double toStop() {
        double d = -progress;
        for (Piece p : pieces) {
            d += p.length();
        }
        return d;
    }

    /** @return whether the robot is on a bend: its cell's piece is an arc */
    boolean bendsFirst() {
        return pieces.get(0).arc();
    }

    /**
     * @param i a cell of the track: 0 the robot's, 1 the first committed one ahead, and so on
     * @return the way to where the track comes into that cell (negative for the robot's own), mm
     */
    double toCell(int i) {
        double d = -progress;
        for (int j = 0; j < i; j++) {
            d += pieces.get(j).length();
        }
        return d;
    }

    /** @return the way to the start of the next bend, 0 on one, or infinity if none lies ahead, mm */
    double toBend() {
        double d = -progress;
        for (Piece p : pieces) {
            if (p.arc()) {
                return Math.max(0, d);
            }
            d += p.length();
        }
        return Double.POSITIVE_INFINITY;
    }

    /**
     * @param ahead mm along the track from the robot's place on it
     * @return the point there, or the track's end if it is nearer
     */
    double[] pointAhead(double ahead) {
        double s = progress + Math.max(0, ahead);
        for (Piece p : pieces) {
            if (s <= p.length()) {
                return p.at(s, radius);
            }
            s -= p.length();
        }
        Piece last = pieces.get(pieces.size() - 1);
        return last.at(last.length(), radius);
    }

    /** @return the direction of the track where the robot is on it, degrees (0 east, 90 north) */
    double headingHere() {
        Piece p = pieces.get(0);
        if (p.arc()) {
            double a = p.a0() + Math.signum(p.sweep()) * (progress / radius + Math.PI / 2);
            return Math.toDegrees(a);
        }
        return Math.toDegrees(Math.atan2(p.y1() - p.y0(), p.x1() - p.x0()));
    }
}
