package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import robosim.env.world.World;

/** A robot's {@code params} is a path relative to the world file, or a shipped name such as {@code p3dx}. */
class WorldShippedParamsTest {
    @TempDir
    Path dir;
    WorldFixtures fixtures;

    @BeforeEach
    void setUp() {
        fixtures = new WorldFixtures(dir);
    }

    private static Path shipped(String file) {
        return WorldFixtures.root().resolve("testLoadFiles/robots").resolve(file).toAbsolutePath().normalize();
    }

    @Test
    void aShippedNameFindsTheShippedFile() {
        World w = fixtures.read("named.xml", """
                <world name="named" width="6000" height="6000">
                  <robot name="r1" type="pioneer" x="1000" y="1000" params="p3dx"/>
                  <robot name="r2" type="pioneer" x="3000" y="1000" params="p3at.xml"/>
                  <robot name="s1" type="scout" x="5000" y="1000" params="scout"/>
                </world>
                """);
        assertEquals(shipped("p3dx.p"), w.robots().get(0).parameterFile());
        assertEquals("p3dx", w.robots().get(0).parameters().subclass());
        assertEquals(shipped("p3at.xml"), w.robots().get(1).parameterFile());
        assertEquals("p3at", w.robots().get(1).parameters().subclass());
        assertEquals(shipped("scout.p"), w.robots().get(2).parameterFile());
    }

    @Test
    void aFileBesideTheWorldComesBeforeAShippedFileOfTheSameName() throws Exception {
        Path own = dir.resolve("environment/p3dx.p");
        Files.writeString(own, Files.readString(shipped("p3dx.p")).replaceFirst("(?m)^RobotWidth\\s+\\S+", "RobotWidth 500"));
        World w = fixtures.read("beside.xml", """
                <world name="beside" width="6000" height="6000">
                  <robot name="r1" type="pioneer" x="1000" y="1000" params="p3dx.p"/>
                </world>
                """);
        assertEquals(own.toAbsolutePath().normalize(), w.robots().get(0).parameterFile());
        assertEquals(500, w.robots().get(0).parameters().robotWidth());
    }

    @Test
    void theSecondExampleInTheFormatDocumentLoadsWithItsShippedNames() throws Exception {
        String doc = Files.readString(WorldFixtures.root().resolve("docs/WORLD-FORMAT.md"));
        int section = doc.indexOf("## A second example");
        int start = doc.indexOf("```xml\n", section) + "```xml\n".length();
        World w = fixtures.read("example.xml", doc.substring(start, doc.indexOf("```", start)));
        assertEquals("example", w.name());
        assertEquals(shipped("p3dx.p"), w.robots().get(0).parameterFile());
        assertEquals(shipped("p3dx.xml"), w.robots().get(1).parameterFile());
        assertEquals(5000, w.gold().x());
    }

    @Test
    void aPathKeepsMeaningAPathRelativeToTheWorldFile() {
        World w = fixtures.read("path.xml", """
                <world name="path" width="6000" height="6000">
                  <robot name="r1" type="pioneer" x="1000" y="1000" params="../robots/p3at.p"/>
                </world>
                """);
        assertEquals(dir.resolve("robots/p3at.p").toAbsolutePath().normalize(), w.robots().get(0).parameterFile());
    }
}
