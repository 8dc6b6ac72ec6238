package robosim.env.core;

import java.util.ArrayList;
import java.util.List;
import robosim.env.world.ForbiddenZone;
import robosim.env.world.HeatSource;
import robosim.env.world.Obstacle;
import robosim.env.world.World;
import robosim.protocol.Snapshot;
import robosim.protocol.WorldDescription;

/** What viewers are sent of a {@link Simulation}: its robots as they are now, and its static world. */
final class Views {
    private Views() {
    }

    /** @return each robot's true pose, odometry, status and readings, in the simulation's order */
    static List<Snapshot.RobotView> robots(List<SimRobot> order) {
        List<Snapshot.RobotView> views = new ArrayList<>(order.size());
        for (SimRobot r : order) {
            Odometry o = r.odometry();
            views.add(new Snapshot.RobotView(r.name, r.x(), r.y(), r.th(), r.stalled(), r.connected,
                    r.sensors().sonarForViewers(), o.x(), o.y(), o.th(), r.sensors().laserForViewers(),
                    r.sensors().laserIncrement(),
                    r.vel(), r.rotVel(), CameraScene.drawn(r)));
        }
        return views;
    }

    /** @return the world's static parts, with the robots in it now (an open world's newcomers too) */
    static WorldDescription description(World world, List<SimRobot> order) {
        List<WorldDescription.Obstacle> obs = new ArrayList<>();
        for (Obstacle o : world.obstacles()) {
            obs.add(new WorldDescription.Obstacle(o.xy(), o.height(), o.color()));
        }
        List<WorldDescription.RobotInfo> infos = new ArrayList<>();
        for (SimRobot r : order) {
            infos.add(new WorldDescription.RobotInfo(r.name, r.type, r.params));
        }
        List<WorldDescription.HeatSource> heat = new ArrayList<>();
        for (HeatSource h : world.heat()) {
            heat.add(new WorldDescription.HeatSource(h.x(), h.y(), h.intensity(), h.equals(world.gold())));
        }
        List<WorldDescription.Zone> zones = new ArrayList<>();
        for (ForbiddenZone z : world.zones()) {
            zones.add(new WorldDescription.Zone(z.area(), z.xy(), z.label()));
        }
        return new WorldDescription(world.name(), world.width(), world.height(), world.stepMs(), obs, infos, heat,
                world.minX(), world.minY(), zones);
    }

    /** @return the world's movable objects where they start */
    static List<WorldDescription.WorldObject> objects(World world) {
        List<WorldDescription.WorldObject> objects = new ArrayList<>();
        for (robosim.env.world.WorldObject o : world.objects()) {
            objects.add(new WorldDescription.WorldObject(o.type(), o.x(), o.y(), o.radius(), o.color()));
        }
        return objects;
    }
}
