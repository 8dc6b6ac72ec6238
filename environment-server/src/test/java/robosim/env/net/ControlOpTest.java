package robosim.env.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.env.core.Simulation;
import robosim.env.world.xml.WorldReader;
import robosim.protocol.ControlRequest;

/** A control client's requests read and checked, in world {@code empty-room.xml} (robots r1 and r2). */
class ControlOpTest {
    private Simulation sim;

    @BeforeEach
    void world() {
        Path p = Path.of("").toAbsolutePath();
        while (!Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        sim = new Simulation(WorldReader.read(p.resolve("testLoadFiles/environment/empty-room.xml")));
    }

    private ControlOp parse(String op, String... args) {
        return ControlOp.parse(new ControlRequest(1, op, List.of(args)), sim);
    }

    private String refusal(String op, String... args) {
        return assertThrows(IllegalArgumentException.class, () -> parse(op, args)).getMessage();
    }

    @Test
    void everyOperationIsReadWithItsValues() {
        assertEquals(new ControlOp.Pause(), parse("pause"));
        assertEquals(new ControlOp.Resume(), parse("resume"));
        assertEquals(new ControlOp.Stop(), parse("stop"));
        assertEquals(new ControlOp.Step(25), parse("step", "25"));
        assertEquals(new ControlOp.Pace(0), parse("pace", "max"));
        assertEquals(new ControlOp.Pace(1), parse("pace", "realtime"));
        assertEquals(new ControlOp.Pace(0.5), parse("pace", "0.5"));
        assertEquals(new ControlOp.Move("r2", 3000, -250.5, 90), parse("move", "r2", "3000", "-250.5", "90"));
        assertEquals(new ControlOp.Remove("r1"), parse("remove", "r1"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "step|0|step N: N is a whole number from 1 to 1000000, got '0'",
        "step|1000001|step N: N is a whole number from 1 to 1000000, got '1000001'",
        "step|2.5|step N: N is a whole number from 1 to 1000000, got '2.5'",
        "pace|0|pace: the pace is max, realtime or a factor of real time from 0.01 to 1000, got '0'",
        "pace|-2|pace: the pace is max, realtime or a factor of real time from 0.01 to 1000, got '-2'",
        "pace|NaN|pace: the pace is max, realtime or a factor of real time from 0.01 to 1000, got 'NaN'",
        "pace|Infinity|pace: the pace is max, realtime or a factor of real time from 0.01 to 1000, got 'Infinity'",
        "pace|fast|pace: the pace is max, realtime or a factor of real time from 0.01 to 1000, got 'fast'",
        "remove|r9|remove: no robot named 'r9' in world empty-room",
    })
    void aBadValueIsRefusedNamingTheValueAndTheRule(String op, String arg, String reason) {
        assertEquals(reason, refusal(op, arg));
    }

    @Test
    void aMoveOutsideTheWorldsCoordinateBoundOrToAnUnknownRobotIsRefused() {
        assertEquals("move: X is a number of mm within 100000000 of the origin, got '1e9'",
                refusal("move", "r1", "1e9", "0", "0"));
        assertEquals("move: Y is a number of mm within 100000000 of the origin, got 'NaN'",
                refusal("move", "r1", "0", "NaN", "0"));
        assertEquals("move: TH is a heading in degrees within 1000000 of 0, got 'north'",
                refusal("move", "r1", "0", "0", "north"));
        assertEquals("move: no robot named 'r9' in world empty-room", refusal("move", "r9", "0", "0", "0"));
    }

    @Test
    void theWrongNumberOfArgumentsIsRefusedWithTheUsage() {
        assertEquals("step takes 1 argument (step N), got 0", refusal("step"));
        assertEquals("move takes 4 arguments (move NAME X Y TH), got 3", refusal("move", "r1", "0", "0"));
        assertEquals("pause takes 0 arguments (pause), got 1", refusal("pause", "now"));
    }

    @Test
    void anUnknownOperationNamesTheKnownOnes() {
        assertEquals("unknown operation 'jump'; the operations are pause, resume, step N, stop,"
                + " pace max|realtime|K, move NAME X Y TH, remove NAME, restart, load WORLD, status, log", refusal("jump"));
    }

    @Test
    void restartTakesNoArgumentAndLoadOne() {
        assertEquals("restart takes 0 arguments (restart), got 1", refusal("restart", "now"));
        assertEquals("load takes 1 argument (load WORLD), got 0", refusal("load"));
    }
}
