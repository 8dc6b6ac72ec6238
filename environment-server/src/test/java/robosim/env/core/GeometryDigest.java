package robosim.env.core;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.locationtech.jts.geom.Polygon;
import robosim.env.world.World;
import robosim.geometry.BodyShape;
import robosim.geometry.GeometryClient;
import robosim.geometry.Pose2D;
import robosim.geometry.Surroundings;
import robosim.geometry.SweepResult;
import robosim.protocol.Bumpers;
import robosim.protocol.Command;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;
import robosim.protocol.TruePose;

/**
 * A SHA-256 of the raw bits of many geometry answers on a world, or of its robots' states over a
 * simulated run: two digests alike mean every answer was alike, to the last bit and in order.
 */
final class GeometryDigest {
    /** Points across and down the world the geometry is asked about. */
    private static final int GRID = 20;
    private static final int STEPS = 60;

    private final MessageDigest sha;

    private GeometryDigest() {
        try {
            sha = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    private void add(double v) {
        long bits = Double.doubleToRawLongBits(v);
        for (int i = 0; i < 8; i++) {
            sha.update((byte) (bits >>> (8 * i)));
        }
    }

    private void add(boolean b) {
        sha.update((byte) (b ? 1 : 0));
    }

    private void add(String s) {
        sha.update(String.valueOf(s).getBytes(StandardCharsets.UTF_8));
        sha.update((byte) 0);
    }

    private String hex() {
        return HexFormat.of().formatHex(sha.digest());
    }

    /**
     * @return the digest of the answers of a {@link GeometryClient} on these obstacles at points on
     *         a grid over the area given, with a round and a rectangular body swept from each
     */
    static String of(List<Polygon> obstacles, double minX, double minY, double width, double height) {
        GeometryDigest d = new GeometryDigest();
        GeometryClient g = new GeometryClient(obstacles);
        BodyShape disc = BodyShape.disc(250, 16);
        int[] bodies = {g.addBody(disc, new Pose2D(minX - 5000, minY - 5000, 0)),
            g.addBody(BodyShape.rectangle(300, 200, 420), new Pose2D(minX - 9000, minY - 5000, 0))};
        SplittableRandom random = new SplittableRandom(11);
        for (int i = 0; i < GRID; i++) {
            for (int j = 0; j < GRID; j++) {
                double x = minX + (i + random.nextDouble()) * width / GRID;
                double y = minY + (j + random.nextDouble()) * height / GRID;
                double th = random.nextDouble() * 2 * Math.PI;
                d.add(g.overlaps(disc, new Pose2D(x, y, th), -1));
                d.ranges(g, x, y, th);
                for (int b : bodies) {
                    d.sweeps(g, b, new Pose2D(x, y, th));
                }
            }
        }
        return d.hex();
    }

    /** Sonar- and laser-like ranges: gathered, as the simulation reads them, and asked directly. */
    private void ranges(GeometryClient g, double x, double y, double th) {
        Surroundings s = g.around(x, y, 8600, -1);
        add(s.size());
        for (int k = 0; k < 32; k++) {
            add(s.ray(x, y, th + k * Math.PI / 16, 8000));
        }
        for (int k = 0; k < 16; k++) {
            add(s.cone(x + 100, y - 50, th + k * Math.PI / 8, Math.toRadians(12.5), 5000));
        }
        for (int k = 0; k < 8; k++) {
            add(g.rayRange(x, y, th + k * Math.PI / 4, 8000, -1));
        }
        for (int k = 0; k < 4; k++) {
            add(g.coneRange(x, y, th + k * Math.PI / 2, 0.2, 3000, -1));
        }
        add(g.lineOfSight(x, y, x + 4000 * Math.cos(th), y + 4000 * Math.sin(th)));
    }

    /** Sweeps a body from a pose three ways, then lists its contacts where the first blocked sweep stopped. */
    private void sweeps(GeometryClient g, int body, Pose2D pose) {
        g.moveBody(body, pose);
        Pose2D stop = null;
        double[][] motions = {{1500, 0}, {1000, 1.0}, {-600, -2.5}};
        for (double[] m : motions) {
            SweepResult r = g.sweep(body, m[0], m[1]);
            add(r.fraction());
            add(r.pose().x());
            add(r.pose().y());
            add(r.pose().th());
            add(r.blocked());
            if (r.blocked() && stop == null) {
                stop = r.pose();
            }
        }
        if (stop != null) {
            g.moveBody(body, stop);
        }
        for (double tolerance : new double[] {1.0, 40}) {
            List<Double> contacts = g.contacts(body, tolerance);
            add(contacts.size());
            for (double a : contacts) {
                add(a);
            }
        }
    }

    /**
     * @return the digest of every robot's state over a run in which the robots, lasers on, drive
     *         and turn, and are placed at random points of the world every 20 steps
     */
    static String ofSimulation(World world) {
        GeometryDigest d = new GeometryDigest();
        Simulation sim = new Simulation(world, 1);
        SplittableRandom random = new SplittableRandom(5);
        List<String> names = sim.robotNames();
        Map<String, List<Command>> start = new HashMap<>();
        for (int i = 0; i < names.size(); i++) {
            start.put(names.get(i), List.of(new Command.ConfigureLaser(true, 1, 8000),
                    new Command.SetVel(300 + 50 * (i % 5)), new Command.SetRotVel(i % 2 == 0 ? 15 : -10)));
        }
        sim.step(start);
        for (int step = 1; step < STEPS; step++) {
            if (step % 20 == 0) {
                for (String name : names) {
                    d.add(sim.place(name, world.minX() + random.nextDouble() * world.width(),
                            world.minY() + random.nextDouble() * world.height(), random.nextDouble() * 360));
                }
            }
            sim.step(Map.of());
            for (String name : names) {
                d.add(sim.state(name));
            }
        }
        return d.hex();
    }

    private void add(RobotState s) {
        for (double v : new double[] {s.x(), s.y(), s.th(), s.vel(), s.rotVel(), s.collisions(), s.get(Bumpers.PART).sectors()}) {
            add(v);
        }
        add(s.stalled());
        for (int[] a : new int[][] {s.get(SonarReading.PART).ranges(), s.get(LaserReading.PART).ranges()}) {
            add(a == null ? -1 : a.length);
            for (int v : a == null ? new int[0] : a) {
                add(v);
            }
        }
        TruePose t = s.get(TruePose.PART);
        if (t != null) {
            add(t.x());
            add(t.y());
            add(t.th());
        }
    }
}
