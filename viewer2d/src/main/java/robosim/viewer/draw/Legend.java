package robosim.viewer.draw;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.RobotParameters;
import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.RobotInfo;

/**
 * What the legend under a picture (2D, or 3D without what only 2D draws) explains: each robot's
 * colour, the states a robot is drawn in, and the things shown in this picture. It follows from the world and the options alone, never
 * from a snapshot, so that every frame of a run has a legend of the same size.
 */
final class Legend {
    /** How an entry's sample is drawn. */
    enum Sample { ROBOT, FRONT, NOT_CONNECTED, GONE, STALLED, ODOMETRY, SONAR, LASER, TRAIL, DRAWING, HEAT, GOLD, WALL,
        FORBIDDEN, GRID }

    /**
     * One entry.
     *
     * @param sample      how its sample is drawn
     * @param label       the words beside it
     * @param robotIndex  for a robot, its index in the world (its colour); otherwise -1
     */
    record Entry(Sample sample, String label, int robotIndex) { }

    private Legend() {
    }

    static List<Entry> entries(WorldDescription world, RenderOptions options) {
        return entries(world, options, false);
    }

    /**
     * @param solid whether for the 3D view, which draws no odometry ghosts, drawings, forbidden
     *              zones or grid, and whose walls need no sample
     */
    static List<Entry> entries(WorldDescription world, RenderOptions options, boolean solid) {
        List<Entry> entries = new ArrayList<>();
        List<RobotInfo> robots = world.robots();
        for (int i = 0; i < robots.size(); i++) {
            entries.add(new Entry(Sample.ROBOT, robots.get(i).name(), i));
        }
        entries.add(new Entry(Sample.FRONT, "front (heading)", -1));
        entries.add(new Entry(Sample.NOT_CONNECTED, "grey: not connected yet", -1));
        entries.add(new Entry(Sample.GONE, "dashed grey: gone (left, dropped or removed)", -1));
        entries.add(new Entry(Sample.STALLED, "red edge: stalled", -1));
        if (options.showOdometry() && !solid) {
            entries.add(new Entry(Sample.ODOMETRY, "dashed: where it believes it is (odometry)", -1));
        }
        if (options.showSonar()) {
            entries.add(new Entry(Sample.SONAR, "sonar rays", -1));
        }
        if (options.showLaser() && hasLaser(robots)) {
            entries.add(new Entry(Sample.LASER, "laser scan", -1));
        }
        if (options.showTrails()) {
            entries.add(new Entry(Sample.TRAIL, "trail", -1));
        }
        if (options.showDrawings() && !solid) {
            entries.add(new Entry(Sample.DRAWING, "translucent: what a robot drew", -1));
        }
        if (world.heat().stream().anyMatch(h -> !h.gold())) {
            entries.add(new Entry(Sample.HEAT, "heat source", -1));
        }
        if (world.heat().stream().anyMatch(WorldDescription.HeatSource::gold)) {
            entries.add(new Entry(Sample.GOLD, "gold (it glows with heat)", -1));
        }
        if (!world.obstacles().isEmpty() && !solid) {
            entries.add(new Entry(Sample.WALL, "wall", -1));
        }
        if (!world.zones().isEmpty() && !solid) {
            entries.add(new Entry(Sample.FORBIDDEN, forbidden(world), -1));
        }
        if (options.showGrid() && !solid) {
            entries.add(new Entry(Sample.GRID, "grid: " + ScaleBar.label(ScaleBar.gridSpacing(Math.max(world.width(), world.height())))
                    + " squares", -1));
        }
        return entries;
    }

    /** @return the forbidden zones' entry, naming the kinds the world has */
    private static String forbidden(WorldDescription world) {
        boolean areas = world.zones().stream().anyMatch(WorldDescription.Zone::area);
        boolean lines = world.zones().stream().anyMatch(z -> !z.area());
        String what = areas && lines ? "forbidden area or line" : areas ? "forbidden area" : "forbidden line";
        return "dashed red: " + what + " (robots' programs keep out; not solid)";
    }

    private static boolean hasLaser(List<RobotInfo> robots) {
        for (RobotInfo info : robots) {
            RobotParameters p = info.parameters();
            if (p != null && p.laserMaxRange() > 0) {
                return true;
            }
        }
        return false;
    }
}
