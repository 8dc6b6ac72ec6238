package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RobotLaunchTest {
    @TempDir
    Path dir;

    @Test
    void aClassOnTheClasspathRunsAsRobotWithTheEnvironmentsRobotPort() {
        RobotLaunch l = RobotLaunch.parse("robosim.examples.wander.Wander", "", "r1", "", "", "");

        assertEquals(List.of("robot", "robosim.examples.wander.Wander", "r1", "127.0.0.1", "5000"),
                l.robotArguments("127.0.0.1", 5000));
        assertTrue(l.placementRequest().isEmpty());
    }

    @Test
    void aJarIsGivenAsTheProgramsClasspath() throws IOException {
        Path jar = Files.createFile(dir.resolve("bot.jar"));

        assertEquals(List.of("robot", "--cp", jar.toString(), "my.Bot", "b1", "h", "6000"),
                RobotLaunch.parse("my.Bot", jar.toString(), "b1", "", "", "").robotArguments("h", 6000));
    }

    @Test
    void aPoseGivenPlacesTheRobotOnceJoinedHeadingZeroWhenLeftOut() {
        assertEquals(new Request("move", List.of("r1", "1000", "2000", "0")),
                RobotLaunch.parse("a.B", "", "r1", "1000", "2000", "").placementRequest().orElseThrow());
    }

    @Test
    void aProgramThatIsNotAClassNameIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RobotLaunch.parse("rm -rf /", "", "r1", "", "", ""));

        assertEquals("Program: a Java class name such as robosim.examples.wander.Wander, got 'rm -rf /'",
                e.getMessage());
    }

    @Test
    void aNameWithSpacesIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RobotLaunch.parse("a.B", "", "robot one", "", "", ""));

        assertEquals("Name: 1 to 64 letters, digits, '_', '.' or '-', got 'robot one'", e.getMessage());
    }

    @Test
    void aMissingJarIsNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RobotLaunch.parse("a.B", dir.resolve("none.jar").toString(), "r1", "", "", ""));

        assertEquals("Jar: no such file or folder: " + dir.resolve("none.jar"), e.getMessage());
    }
}
