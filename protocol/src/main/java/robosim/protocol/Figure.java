package robosim.protocol;

import java.util.Arrays;
import java.util.Objects;
import java.util.Set;

/**
 * A shape a robot draws into the world's views (MobileEyes' "drawings"), in world mm: its known
 * map, the frontier it claimed. Viewers draw it translucent, under the robots and over the floor.
 *
 * <p>The kinds and what {@code xy} holds for each:
 * <ul>
 *   <li>{@value #CELLS}: filled axis-aligned rectangles, {@code x0, y0, x1, y1} repeated;</li>
 *   <li>{@value #LINE}: a polyline, {@code x, y} for each of at least 2 points;</li>
 *   <li>{@value #POLYGON}: a filled closed ring, {@code x, y} for each of at least 3 points;</li>
 *   <li>{@value #DOTS}: points, {@code x, y} for each of at least 1.</li>
 * </ul>
 *
 * <p>Its constructor checks every value, so a figure that breaks a rule cannot exist, on the
 * robot's side or decoded from the wire. Two figures are equal when their kinds, colours and
 * numbers are.
 *
 * @param kind  {@value #CELLS}, {@value #LINE}, {@value #POLYGON} or {@value #DOTS}
 * @param color a colour's name or {@code #rrggbb} as {@link Colors} reads it, kept as {@code #rrggbb};
 *              empty (or null) for the robot's own colour in the viewer
 * @param xy    the coordinates, mm, world frame; finite, at most {@value #MAX_NUMBERS}
 */
public record Figure(String kind, String color, double[] xy) {
    /** Filled axis-aligned rectangles. */
    public static final String CELLS = "cells";
    /** A polyline. */
    public static final String LINE = "line";
    /** A filled closed ring. */
    public static final String POLYGON = "polygon";
    /** Points. */
    public static final String DOTS = "dots";
    /** The most numbers in one figure, and in all the figures of one drawing. */
    public static final int MAX_NUMBERS = 20_000;

    private static final Set<String> KINDS = Set.of(CELLS, LINE, POLYGON, DOTS);

    /**
     * @throws IllegalArgumentException naming the value and the rule, if the kind is unknown, the
     *                                  colour is not one, a coordinate is not finite, or the number
     *                                  of coordinates does not fit the kind or the cap
     */
    public Figure {
        if (kind == null || !KINDS.contains(kind)) {
            throw new IllegalArgumentException("'" + kind + "' was supplied for a figure's kind: it is one of "
                    + CELLS + ", " + LINE + ", " + POLYGON + " or " + DOTS);
        }
        color = color == null || color.isBlank() ? "" : Colors.format(Colors.parse(color));
        if (xy == null) {
            throw new IllegalArgumentException("a " + kind + " figure needs its coordinates, xy");
        }
        if (xy.length > MAX_NUMBERS) {
            throw new IllegalArgumentException(xy.length + " numbers were supplied for a " + kind
                    + " figure: at most " + MAX_NUMBERS);
        }
        int group = CELLS.equals(kind) ? 4 : 2;
        int least = switch (kind) {
            case CELLS -> 4;
            case LINE -> 4;
            case POLYGON -> 6;
            default -> 2;
        };
        if (xy.length < least || xy.length % group != 0) {
            throw new IllegalArgumentException(xy.length + " numbers were supplied for a " + kind + " figure: "
                    + (CELLS.equals(kind) ? "4 (x0, y0, x1, y1) per cell" : "2 (x, y) per point")
                    + ", at least " + least);
        }
        xy = xy.clone();
        for (int i = 0; i < xy.length; i++) {
            if (!Double.isFinite(xy[i])) {
                throw new IllegalArgumentException(xy[i] + " was supplied for xy[" + i + "] of a " + kind
                        + " figure: it must be a finite number");
            }
        }
    }

    /** @return a copy of the coordinates, mm */
    @Override
    public double[] xy() {
        return xy.clone();
    }

    /** @return how many coordinates the figure has, without copying them */
    public int size() {
        return xy.length;
    }

    /**
     * @param i an index from 0 to {@link #size()} - 1
     * @return that coordinate, mm, without copying the others
     */
    public double at(int i) {
        return xy[i];
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Figure f && kind.equals(f.kind) && color.equals(f.color) && Arrays.equals(xy, f.xy);
    }

    @Override
    public int hashCode() {
        return Objects.hash(kind, color, Arrays.hashCode(xy));
    }

    @Override
    public String toString() {
        return "Figure[" + kind + (color.isEmpty() ? "" : " " + color) + ", " + xy.length + " numbers]";
    }
}
