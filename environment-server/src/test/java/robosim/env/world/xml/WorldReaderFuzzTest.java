package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import robosim.env.core.Simulation;
import robosim.env.world.HeatSource;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.protocol.Fuzz;

/**
 * World files, a literal one with every element and two shipped ones, damaged at random (see
 * {@link Fuzz} to replay a case or run more): numbers swapped for NaN, infinities, huge and
 * malformed ones; names swapped and lengthened; elements repeated, dropped, nested thousands deep;
 * DOCTYPEs, entities and control characters; bytes flipped. Each read gives a world the
 * Environment can load, every number in it finite and every robot and heat source inside it, or a
 * {@link WorldFileException} naming the file and one of its lines.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WorldReaderFuzzTest {
    /** Every element of the format, each attribute given. */
    private static final String EVERY_ELEMENT = """
            <?xml version="1.0" encoding="UTF-8"?>
            <world name="every-element" width="8000" height="6000" stepMs="100" boundary="true">
              <noise sonar="5" laser="10" odometry="0.0075"/>
              <comms range="8000" wallsBlock="true" latency="1" loss="0.05" maxBytes="65536"/>
              <wall x1="3000" y1="100" x2="3000" y2="4000" thickness="100" height="500"/>
              <polygon points="5000,1500 6200,1500 5600,2600" height="300"/>
              <robot name="r1" type="pioneer" x="1000" y="1000" th="45" params="../robots/p3dx.p"/>
              <heat x="4500" y="5000" intensity="40"/>
              <robot name="s1" type="scout" x="6500" y="4500" th="-90" params="../robots/scout.p"/>
              <gold x="7000" y="5500" intensity="20"/>
              <robot name="r2" type="pioneer" x="1500" y="4500" params="../robots/p3at.p"/>
            </world>
            """;

    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() throws IOException {
        fixtures = new WorldFixtures(dir);
        fixtures.writeRobot("scout.p", Files.readString(WorldFixtures.root().resolve("testLoadFiles/robots/scout.p")));
    }

    @ParameterizedTest
    @ValueSource(strings = {"every-element.xml", "cluttered-room.xml", "mixed-team.xml"})
    void aDamagedWorldIsReadOrRefusedNamingItsLine(String world) throws IOException {
        String valid = world.equals("every-element.xml") ? EVERY_ELEMENT
                : Files.readString(WorldFixtures.root().resolve("testLoadFiles/environment").resolve(world));
        Path file = fixtures.write(world, valid);
        fixtures.read(world, valid);
        Fuzz.cases(0x5EED_0401L + world.hashCode(), 800, fuzz -> {
            byte[] bytes = fuzz.random().nextInt(5) == 0 ? fuzz.mutate(valid.getBytes(StandardCharsets.UTF_8))
                    : fuzz.mutateText(valid).getBytes(StandardCharsets.UTF_8);
            Files.write(file, bytes);
            fuzz.input(new String(bytes, StandardCharsets.UTF_8));

            World read;
            try {
                read = WorldReader.read(file);
            } catch (WorldFileException e) {
                String where = e.line() > 0 ? file + ":" + e.line() + ": " : file + ": ";
                assertEquals(where + e.rule(), e.getMessage());
                assertEquals(file, e.file());
                assertTrue(e.line() >= 0 && e.line() <= Fuzz.lines(bytes), "a line of the file: " + e.getMessage());
                assertFalse(e.rule().isBlank(), "a rule: " + e.getMessage());
                return;
            }
            loadable(read);
        });
    }

    /** The checks of the format hold, and the Environment's core takes the world as it is. */
    private static void loadable(World w) {
        assertTrue(w.width() > 0 && w.width() <= World.MAX_SIZE && w.height() > 0 && w.height() <= World.MAX_SIZE,
                "the world's size: " + w);
        for (Obstacle o : w.obstacles()) {
            for (double v : o.xy()) {
                assertTrue(Double.isFinite(v), "an obstacle's corners: " + o);
            }
            assertTrue(o.polygon().isValid(), "an obstacle is a valid polygon: " + o);
        }
        for (RobotSpec r : w.robots()) {
            assertTrue(r.x() >= 0 && r.x() <= w.width() && r.y() >= 0 && r.y() <= w.height()
                    && Double.isFinite(r.th()), "a robot inside the world: " + r);
        }
        for (HeatSource h : w.heat()) {
            assertTrue(h.x() >= 0 && h.x() <= w.width() && h.y() >= 0 && h.y() <= w.height()
                    && Double.isFinite(h.intensity()) && h.intensity() > 0, "a heat source inside the world: " + h);
        }
        new Simulation(w, 1).step(java.util.Map.of());
    }
}
