package robosim.panel.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class RequestTest {
    @Test
    void theRunButtonsSendTheirOperationWithoutArguments() {
        assertEquals(List.of("pause", "resume", "stop"),
                List.of(Request.pause().op(), Request.resume().op(), Request.stop().op()));
        assertEquals(List.of(), Request.pause().args());
    }

    @Test
    void restartSendsTheOperationAlone() {
        assertEquals(new Request("restart", List.of()), Request.restart());
    }

    @Test
    void loadSendsAFileThatExistsHereAsItsAbsolutePath(@TempDir Path dir) throws Exception {
        Path world = Files.writeString(dir.resolve("maze.xml"), "<world/>");

        assertEquals(new Request("load", List.of(world.toAbsolutePath().toString())),
                Request.load(" " + dir.resolve("./maze.xml") + " "));
    }

    @Test
    void loadSendsANameNotFoundHereAsTypedForTheEnvironmentToFindBesideItsWorld() {
        assertEquals(new Request("load", List.of("small-maze.xml")), Request.load("small-maze.xml"));
    }

    @Test
    void loadRefusesAnEmptyChoice() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Request.load("  "));

        assertEquals("Load: choose or type a world file first", e.getMessage());
    }

    @Test
    void stepSendsTheNumberTyped() {
        assertEquals(new Request("step", List.of("25")), Request.step(" 25 "));
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "-3", "1000001", "ten", ""})
    void stepRefusesANumberOutsideOneToAMillionNamingTheField(String typed) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Request.step(typed));

        assertEquals("Steps: a whole number from 1 to 1000000, got '" + typed + "'", e.getMessage());
    }

    @Test
    void moveSendsThePoseAsAUserTypesIt() {
        assertEquals(new Request("move", List.of("r1", "3000", "-1500.5", "90")),
                Request.move("r1", "3000", "-1500.5", "90.0"));
    }

    @Test
    void moveRefusesACoordinateThatIsNotANumber() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Request.move("r1", "3000", "north", "0"));

        assertEquals("Y: a number within 100000000 of 0, got 'north'", e.getMessage());
    }

    @Test
    void removeNamesTheRobot() {
        assertEquals("remove r2", Request.remove("r2").toString());
    }

    @Test
    void paceSendsTheStopsWord() {
        assertEquals(new Request("pace", List.of("realtime")), Request.pace(Pace.STOPS.get(Pace.REALTIME)));
        assertEquals(new Request("pace", List.of("max")), Request.pace(Pace.STOPS.get(Pace.MAX)));
    }
}
