package robosim.examples.aria;

import java.util.ArrayList;
import java.util.List;
import robosim.aria.ArLineSegment;
import robosim.aria.ArMap;
import robosim.aria.ArMapObject;
import robosim.aria.ArPose;

/**
 * A route that keeps off a map's forbidden lines and areas: the straight leg to the goal, or, when
 * that leg crosses a forbidden segment, a way round one of the segment's ends, {@code clearance} mm
 * past it, whichever is shorter and clear (trying further detours, a few deep, when neither is).
 * Small on purpose: an example of planning on {@link ArMap}, not ARIA's path planner.
 */
final class MapRoute {
    /** How many detours one leg may take before the planner gives up on it. */
    private static final int MAX_DEPTH = 3;

    private final List<ArLineSegment> forbidden = new ArrayList<>();
    private final double clearance;

    /**
     * @param map       the map, with its forbidden lines and areas
     * @param clearance how far past a forbidden segment's end a detour goes, mm
     */
    MapRoute(ArMap map, double clearance) {
        this.clearance = clearance;
        for (ArMapObject obj : map.findMapObjectsOfType("ForbiddenLine")) {
            forbidden.add(obj.getFromToSegment());
        }
        for (ArMapObject obj : map.findMapObjectsOfType("ForbiddenArea")) {
            forbidden.addAll(obj.getFromToSegments());
        }
    }

    /** @return the forbidden segments: the lines, and each area's four sides */
    List<ArLineSegment> forbidden() {
        return forbidden;
    }

    /**
     * @param from where the robot is
     * @param to   the goal
     * @return the waypoints to drive through, the goal last; null if no route was found
     */
    List<ArPose> plan(ArPose from, ArPose to) {
        return plan(from, to, 0);
    }

    private List<ArPose> plan(ArPose from, ArPose to, int depth) {
        ArLineSegment blocking = firstCrossed(from, to);
        if (blocking == null) {
            List<ArPose> route = new ArrayList<>();
            route.add(new ArPose(to.getX(), to.getY()));
            return route;
        }
        if (depth == MAX_DEPTH) {
            return null;
        }
        List<ArPose> best = null;
        double bestLength = Double.MAX_VALUE;
        for (ArPose via : detours(blocking)) {
            List<ArPose> first = plan(from, via, depth + 1);
            List<ArPose> rest = first == null ? null : plan(via, to, depth + 1);
            if (rest == null) {
                continue;
            }
            first.addAll(rest);
            double length = length(from, first);
            if (length < bestLength) {
                best = first;
                bestLength = length;
            }
        }
        return best;
    }

    /** @return the forbidden segment the leg crosses nearest {@code from}, or null */
    private ArLineSegment firstCrossed(ArPose from, ArPose to) {
        ArLineSegment leg = new ArLineSegment(from, to);
        ArLineSegment nearest = null;
        double nearestDistance = Double.MAX_VALUE;
        ArPose at = new ArPose();
        for (ArLineSegment f : forbidden) {
            if (leg.intersects(f, at) && from.findDistanceTo(at) < nearestDistance) {
                nearest = f;
                nearestDistance = from.findDistanceTo(at);
            }
        }
        return nearest;
    }

    /** @return a point {@code clearance} past each end of the segment, along it */
    private List<ArPose> detours(ArLineSegment s) {
        double length = s.getLengthOf();
        double ux = length > 0 ? (s.getX2() - s.getX1()) / length : 1;
        double uy = length > 0 ? (s.getY2() - s.getY1()) / length : 0;
        return List.of(new ArPose(s.getX1() - ux * clearance, s.getY1() - uy * clearance),
                new ArPose(s.getX2() + ux * clearance, s.getY2() + uy * clearance));
    }

    private static double length(ArPose from, List<ArPose> route) {
        double sum = 0;
        ArPose at = from;
        for (ArPose p : route) {
            sum += at.findDistanceTo(p);
            at = p;
        }
        return sum;
    }
}
