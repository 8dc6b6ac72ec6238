package robosim.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import robosim.env.core.Simulation;
import robosim.env.world.Obstacle;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;
import robosim.map.MapFile;
import robosim.map.MapReader;
import robosim.protocol.Command;

/**
 * What a large ARIA map costs: reading it into a world (the map read, points merged, the robot
 * placed), building the simulation on it, and a simulation step of its robot with sonar and a
 * laser on, with the points merged as the world has them and, for comparison, as one square each.
 */
public final class MapLoadBench {
    /** Side of a room of the generated building, mm. */
    private static final int ROOM = 4000;
    /** Spacing of the generated points, mm: the map's resolution, as a scanned map's are. */
    private static final int RESOLUTION = 20;
    /** Steps per timed batch. */
    private static final int STEPS = 50;
    private static final double LASER_RANGE = 8000;

    private MapLoadBench() {
    }

    /**
     * The figures of one map.
     *
     * @param map         the map's file name
     * @param points      its points
     * @param lines       its lines
     * @param obstacles   the world's obstacles after merging
     * @param readSeconds reading the map into a world, the best of the runs after the first
     * @param firstRead   the first run (the JIT still cold), s
     * @param worldMb     the heap the world keeps, after a garbage collection, MB
     * @param heapMb      the most heap this JVM may use, MB
     * @param simSeconds  building the simulation on the world, best run, s; NaN when not measured
     * @param firstSim    the first run, s; NaN when not measured
     * @param stepMerged  one step of the robot turning with its sonar and 181-beam laser on, merged, µs;
     *                    NaN when not measured
     * @param stepSquares the same step with one square per point, µs; NaN when not measured
     */
    public record Result(String map, int points, int lines, int obstacles, double readSeconds, double firstRead,
                         long worldMb, long heapMb, double simSeconds, double firstSim, double stepMerged,
                         double stepSquares) {
    }

    /**
     * Writes a generated scanned building, its points on a 20 mm lattice as a scanner's are: a grid
     * of 4 m rooms whose walls are rows and columns of points two deep, with a door in each inner
     * wall (70 % of the points); in each room a slanted wall (a slope of one in three, as a scan of
     * a wall at an angle lies on the lattice; 15 %); and furniture, 3 x 3 clusters of points
     * scattered from a fixed seed, kept 1 m clear of the robot's home in the first room (15 %).
     *
     * @param file   where
     * @param points how many points, at least 1000
     * @return the file
     * @throws IOException if it cannot be written
     */
    public static Path generate(Path file, int points) throws IOException {
        List<int[]> xy = new ArrayList<>(points);
        int wallPoints = points * 7 / 10;
        int rooms = rooms(points);
        int size = rooms * ROOM;
        for (int k = 0; k <= rooms && xy.size() < wallPoints; k++) {
            for (int t = 0; t <= size / RESOLUTION && xy.size() < wallPoints; t++) {
                int along = t * RESOLUTION;
                if (along % ROOM > ROOM / 2 - 500 && along % ROOM < ROOM / 2 + 500 && k > 0 && k < rooms) {
                    continue; // a door
                }
                for (int deep = 0; deep < 2; deep++) {
                    xy.add(new int[] {along, k * ROOM + deep * RESOLUTION});
                    xy.add(new int[] {k * ROOM + deep * RESOLUTION, along});
                }
            }
        }
        int slanted = xy.size() + points * 15 / 100;
        for (int room = 0; xy.size() < slanted; room = (room + 1) % (rooms * rooms)) {
            int x0 = (room % rooms) * ROOM + 600;
            int y0 = (room / rooms) * ROOM + 2600;
            for (int t = 0; t < 120 && xy.size() < slanted; t++) {
                xy.add(new int[] {x0 + t * RESOLUTION, y0 + (t / 3) * RESOLUTION});
            }
        }
        SplittableRandom random = new SplittableRandom(1);
        while (xy.size() < points) {
            int x = random.nextInt(size / RESOLUTION - 3) * RESOLUTION;
            int y = random.nextInt(size / RESOLUTION - 3) * RESOLUTION;
            if (Math.hypot(x - ROOM / 2.0, y - ROOM / 2.0) < 1000) {
                continue;
            }
            for (int k = 0; k < 9 && xy.size() < points; k++) {
                xy.add(new int[] {x + (k % 3) * RESOLUTION, y + (k / 3) * RESOLUTION});
            }
        }
        try (BufferedWriter w = header(file, size, xy.size())) {
            for (int[] p : xy) {
                w.write(p[0] + " " + p[1] + "\n");
            }
        }
        return file;
    }

    /**
     * Writes a map of points scattered uniformly at random, whole millimetres from a fixed seed,
     * over the square the building of {@link #generate} with as many points covers, kept 1 m clear
     * of the robot's home: hardly two points line up, so nearly every point stays an obstacle of
     * its own, the most a map of that many points can cost.
     *
     * @param file   where
     * @param points how many points, at least 1000
     * @return the file
     * @throws IOException if it cannot be written
     */
    public static Path generateRandom(Path file, int points) throws IOException {
        int size = rooms(points) * ROOM;
        SplittableRandom random = new SplittableRandom(1);
        try (BufferedWriter w = header(file, size, points)) {
            for (int n = 0; n < points; ) {
                int x = random.nextInt(size + 1);
                int y = random.nextInt(size + 1);
                if (Math.hypot(x - ROOM / 2.0, y - ROOM / 2.0) >= 1000) {
                    w.write(x + " " + y + "\n");
                    n++;
                }
            }
        }
        return file;
    }

    /** @return the rooms along each side of the generated building of so many points */
    private static int rooms(int points) {
        int rooms = 1;
        while (4L * (rooms + 2) * (rooms + 1) * ROOM / RESOLUTION <= points * 7 / 10) {
            rooms++;
        }
        return rooms;
    }

    /** @return a writer of the file, its header and one RobotHome written, at its DATA section */
    private static BufferedWriter header(Path file, int size, int points) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        BufferedWriter w = Files.newBufferedWriter(file);
        w.write("2D-Map\nMinPos: 0 0\nMaxPos: " + size + " " + size + "\nNumPoints: " + points
                + "\nResolution: " + RESOLUTION + "\nCairn: RobotHome " + ROOM / 2 + " " + ROOM / 2
                + " 0 \"\" ICON \"Home\"\nDATA\n");
        return w;
    }

    /**
     * @param map      a map file
     * @param runs     how many times to read it, at least 2 (the first warms the JIT)
     * @param readOnly whether to time the reading alone, not the simulation and its steps
     * @return the figures
     */
    public static Result run(Path map, int runs, boolean readOnly) {
        double first = 0;
        double best = Double.MAX_VALUE;
        World world = null;
        for (int r = 0; r < runs; r++) {
            world = null; // the world before is garbage while the next is read
            long t0 = System.nanoTime();
            world = WorldReader.read(map);
            double s = (System.nanoTime() - t0) / 1e9;
            first = r == 0 ? s : first;
            best = r == 0 ? best : Math.min(best, s);
        }
        long worldMb = retainedMb();
        long heapMb = Runtime.getRuntime().maxMemory() >> 20;
        String name = map.getFileName().toString();
        MapFile file = MapReader.read(map);
        int obstacles = world.obstacles().size();
        if (readOnly) {
            return new Result(name, file.pointCount(), file.lineCount(), obstacles, best, first, worldMb, heapMb,
                    Double.NaN, Double.NaN, Double.NaN, Double.NaN);
        }
        double sim = Double.MAX_VALUE;
        double firstSim = 0;
        Simulation built = null;
        for (int r = 0; r < runs; r++) {
            built = null; // as for the worlds
            long t0 = System.nanoTime();
            built = new Simulation(world, 1);
            double s = (System.nanoTime() - t0) / 1e9;
            firstSim = r == 0 ? s : firstSim;
            sim = r == 0 ? sim : Math.min(sim, s);
        }
        double merged = step(built);
        built = null;
        // with nothing merged (no points, or none that line up) the squares are the world itself
        boolean same = obstacles == file.pointCount() + file.lineCount();
        double squares = same ? merged : step(new Simulation(squaresWorld(file, world), 1));
        return new Result(name, file.pointCount(), file.lineCount(), obstacles, best, first, worldMb, heapMb, sim,
                firstSim, merged, squares);
    }

    /** @return the heap in use after a garbage collection, MB */
    private static long retainedMb() {
        System.gc();
        Runtime rt = Runtime.getRuntime();
        return (rt.totalMemory() - rt.freeMemory()) >> 20;
    }

    private static World squaresWorld(MapFile file, World world) {
        return new World(world.name(), world.source(), world.width(), world.height(), world.stepMs(),
                squares(file, world), world.robots(), List.of(), world.noise(), world.comms(), null, world.minX(),
                world.minY(), world.zones());
    }

    /** The world's lines as they are, and each point as a square of the map's resolution. */
    private static List<Obstacle> squares(MapFile file, World world) {
        List<Obstacle> out = new ArrayList<>(world.obstacles().subList(0, file.lineCount()));
        double[] p = file.points();
        double h = file.resolution() > 0 ? file.resolution() / 2 : RESOLUTION / 2.0;
        int[] lines = file.pointLines();
        for (int i = 0; i < p.length; i += 2) {
            out.add(new Obstacle(new double[] {p[i] - h, p[i + 1] - h, p[i] + h, p[i + 1] - h, p[i] + h,
                p[i + 1] + h, p[i] - h, p[i + 1] + h}, 500, lines[i / 2]));
        }
        return out;
    }

    /** @return microseconds per step of the robots turning in place with sonar and laser on, best of several batches */
    private static double step(Simulation sim) {
        Map<String, List<Command>> first = new HashMap<>();
        for (String name : sim.robotNames()) {
            first.put(name, List.of(new Command.SetRotVel(20), new Command.ConfigureLaser(true, 1, LASER_RANGE)));
        }
        sim.step(first);
        double best = Double.MAX_VALUE;
        for (int batch = 0; batch < 10; batch++) {
            long t0 = System.nanoTime();
            for (int s = 0; s < STEPS; s++) {
                sim.step(Map.of());
            }
            best = Math.min(best, (System.nanoTime() - t0) / 1e3 / STEPS);
        }
        return best;
    }

    /**
     * @param out where
     * @param r   the figures
     */
    public static void print(PrintWriter out, Result r) {
        out.printf(Locale.ROOT, "map load: %s, %d points and %d lines -> %d obstacles: read into a world in %.0f ms"
                        + " (first run %.0f ms); the world keeps %d MB of heap (of %d MB)",
                r.map(), r.points(), r.lines(), r.obstacles(), r.readSeconds() * 1e3, r.firstRead() * 1e3,
                r.worldMb(), r.heapMb());
        if (!Double.isNaN(r.simSeconds())) {
            out.printf(Locale.ROOT, "; simulation built in %.0f ms (first run %.0f ms); a step of its robot"
                            + " turning with sonar and a 181-beam laser %.0f us (%.0f us with one square per point)",
                    r.simSeconds() * 1e3, r.firstSim() * 1e3, r.stepMerged(), r.stepSquares());
        }
        out.println();
        out.flush();
    }
}
