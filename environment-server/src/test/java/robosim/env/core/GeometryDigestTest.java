package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.locationtech.jts.geom.Polygon;
import robosim.env.world.Obstacle;
import robosim.env.world.World;
import robosim.env.world.xml.WorldReader;

/**
 * The geometry answers exactly as it did when these digests were recorded: for each world, a
 * SHA-256 of the raw bits of thousands of answers ({@link GeometryDigest}: sonar cones and laser
 * rays through {@code Surroundings} and directly, lines of sight, overlaps, sweeps of round and
 * rectangular bodies, and the contacts found where the sweeps stop, in their order), and of every
 * robot's state (pose, sonar, laser, bumpers, collisions) over steps of a simulation that drives
 * its robots about. A change to how the obstacles are indexed or numbered must leave both alike.
 */
class GeometryDigestTest {
    @TempDir
    Path dir;

    private static Path root() {
        String property = System.getProperty("robosim.root");
        for (Path p = Path.of(property != null ? property : "").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("testLoadFiles"))) {
                return p;
            }
        }
        throw new IllegalStateException("no testLoadFiles directory");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
        "empty-room.xml, d066416bb3c327f87bfbabd67bfc997418d6c586535d46288803ac1006bb61b9, "
            + "56bbfe2fe4fba03ffa5f771c9a75d4899281f30ce38acd4b5cfdf2cc5f3d204c",
        "cluttered-room.xml, a2d7f184ac962e094d60ffda10a7d70b69e38b8ff5f6c9759d81c936eef7a5e3, "
            + "e803bbd86dbc545f68ea561f09c24e0de4cd2ead4ae5bd4ed7def8c6f136177b",
        "color-room.xml, cc91592780f3f98d74bce3a1a40f7f70a87133f42d70a89ab641781e71afb362, "
            + "2afe7ef2c3b8b4686e971875f64859260c93a40a405249506094f993934b997c",
        "mixed-team.xml, 2780ee53b2fcf5c41f64802c8e77f8220c39167a06c16d40b5b9770b4fb88073, "
            + "d82011461c4b58cf27731cfa3289d33c9612415ca6dfea7c95004846865d316f",
        "small-maze.xml, c82c577b989d6f8eaca78ea9feed7892cd66bf64f2a3f3d4423720daba2cf888, "
            + "d3987d9e127cb59f68798502f0ddb834bcd78003c908133084013582cb3ab806",
        "maze-small.xml, 7539b7d99841d3911b5cb2cbb1746ae8703e17862c40609a8213904408e75ce8, "
            + "70f6a2693a510d2137cac0a2512cb2b2cc57181a67805ba4ee07091f5b09b61f",
        "maze-medium.xml, 8ce4ebd30c11259785a96fa1590c73bbd1077daa0f720bd6dc32e54d872f5dd8, "
            + "62fe9d4f23207428d581f62f5ef48e5eabd60a2171aadeaf5449ad7788f225e5",
        "maze-large.xml, 597ab3f029d3e9bb77255e11a581103dfd871ed244dc88061cee427dcbb6a93b, "
            + "1a5c8749af0dcbf2bb9f1f58ed2de766d3e2cc7ebc745d78a955132b9f6e2485",
        "office.map, 65a18bf81274d1f8f9a2ab54b337fea83f5d0d5e40fc65b5f1060b76a18c3630, "
            + "9048aeda8e98e0b4bd55f29296e29ad874d8e56d1d4e26377907a77afb895dec",
    })
    void shippedWorldsAnswerAsRecorded(String file, String geometry, String simulation) {
        World world = WorldReader.read(root().resolve("testLoadFiles/environment").resolve(file));
        assertDigests(world, geometry, simulation);
    }

    /** AriaCoda's scanned map, where it has been put (it does not ship with RoboSim). */
    @Test
    void columbiaMapAnswersAsRecorded() {
        Path map = Path.of(System.getProperty("robosim.columbia", "/tmp/ariacoda/maps/columbia.map"));
        assumeTrue(Files.isRegularFile(map), "no columbia.map at " + map);
        assertDigests(WorldReader.read(map), "1422415c827ef0d0d9cfbbb71c1f7a94d007e598ddd8a15650816e55680196ce",
                "d2ec574ef245d4845e69443a86ffbbe39027b100173bae7a54269f71cacfe99d");
    }

    @Test
    void aGeneratedMapOfRandomPointsAndLinesAnswersAsRecorded() {
        assertDigests(WorldReader.read(randomMap(dir.resolve("random.map"))),
                "74c4de0fc1cb036a27033bf696109f77592efe18ed5ea62b95603d3644e202b1",
                "ee515f65edf958fe4629fbd08b1d55308accb2ab44d7a6ac30d19e540a1e36cc");
    }

    /** Obstacles whose edges share their centres, lie on both signs of zero, and repeat exactly. */
    @Test
    void tiesAndDuplicatesAnswerAsRecorded() {
        List<Polygon> obstacles = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            double x = (i % 8) * 700 - 2800;
            double y = (i / 8) * 700 - 1800;
            double[] square = {x, y, x + 300, y, x + 300, y + 300, x, y + 300};
            obstacles.add(new Obstacle(square, 500, 0).polygon());
            obstacles.add(new Obstacle(square, 500, 0).polygon());
            obstacles.add(new Obstacle(new double[] {-x - 300, -0.0, -x, 0.0, -x, 120, -x - 300, 120}, 500, 0).polygon());
        }
        assertEquals("5b7f07158c3e6407c4f397e0cba2cf287eac3f3d6ee7f91c3fca317325fb0fef", GeometryDigest.of(obstacles, -4000, -4000, 8000, 8000));
    }

    private static void assertDigests(World world, String geometry, String simulation) {
        List<Polygon> obstacles = new ArrayList<>();
        for (Obstacle o : world.obstacles()) {
            obstacles.add(o.polygon());
        }
        assertEquals(geometry, GeometryDigest.of(obstacles, world.minX(), world.minY(), world.width(),
                world.height()), "geometry of " + world.name());
        assertEquals(simulation, GeometryDigest.ofSimulation(world), "simulation of " + world.name());
    }

    /** A map of 20 000 random points (most stay obstacles of their own) and 2 000 random walls. */
    private static Path randomMap(Path file) {
        int size = 60000;
        SplittableRandom random = new SplittableRandom(3);
        try (Writer w = Files.newBufferedWriter(file)) {
            w.write("2D-Map\nMinPos: 0 0\nMaxPos: " + size + " " + size + "\nNumPoints: 20000\nNumLines: 2000\n"
                    + "Resolution: 20\nCairn: RobotHome 2000 2000 0 \"\" ICON \"Home\"\n"
                    + "Cairn: RobotHome 30000 30000 0 \"\" ICON \"Home\"\nLINES\n");
            for (int n = 0; n < 2000; ) {
                int x = random.nextInt(size);
                int y = random.nextInt(size);
                int x2 = x + random.nextInt(-1500, 1501);
                int y2 = y + random.nextInt(-1500, 1501);
                if (clear(x, y) && clear(x2, y2)) {
                    w.write(x + " " + y + " " + x2 + " " + y2 + "\n");
                    n++;
                }
            }
            w.write("DATA\n");
            for (int n = 0; n < 20000; ) {
                int x = random.nextInt(size + 1);
                int y = random.nextInt(size + 1);
                if (clear(x, y)) {
                    w.write(x + " " + y + "\n");
                    n++;
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return file;
    }

    private static boolean clear(int x, int y) {
        return Math.hypot(x - 2000, y - 2000) > 2500 && Math.hypot(x - 30000, y - 30000) > 2500;
    }
}
