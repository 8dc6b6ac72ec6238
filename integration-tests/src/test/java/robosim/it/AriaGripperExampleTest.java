package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import robosim.cli.Background;
import robosim.env.world.xml.WorldReader;
import robosim.examples.aria.GripperExample;
import robosim.protocol.Snapshot;

/**
 * ARIA's gripperExample ported line for line ({@code examples/aria}), run as the C++ runs: keys on
 * its terminal, against a RoboSim Environment in lockstep ({@code NAME HOST PORT}) and against
 * RoboSim's Pioneer port ({@code -rh}/{@code -rrtp}), where ARIA's gripper query is answered with a
 * gripper packet and the switches come in the SIPs.
 */
@Timeout(value = 3, unit = TimeUnit.MINUTES)
class AriaGripperExampleTest {
    @TempDir
    Path dir;

    /**
     * r1, a p3dx with a gripper, facing +x with a puck between its open paddles: the puck's centre
     * 50 mm ahead of the body, on the inner break beam.
     */
    private Path world(String params) throws Exception {
        return Files.writeString(dir.resolve("gripper.xml"), """
                <world name="gripper" width="8000" height="6000" boundary="true">
                  <robot name="r1" type="pioneer" x="1240" y="3000" th="0" params="%s"/>
                  <object x="1500" y="3000" color="red"/>
                </world>
                """.formatted(LocalEnvironment.root().resolve("testLoadFiles/robots").resolve(params)));
    }

    /** The runs of equal state lines the example logged each cycle, as {@code uniq -c} counts them. */
    private static List<String> stateRuns(String out) {
        List<String> runs = new ArrayList<>();
        String last = null;
        int n = 0;
        for (String line : out.lines().filter(l -> l.startsWith("Lift:")).toList()) {
            if (!line.equals(last) && last != null) {
                runs.add(n + " " + last);
                n = 0;
            }
            last = line;
            n++;
        }
        if (last != null) {
            runs.add(n + " " + last);
        }
        return runs;
    }

    private static final String INNER = "BreakBeam:      inner\n";
    /** The Escape key alone: the key handler attached to the robot exits the program. */
    private static final int ESC = 27;
    /** The lift has come to its end with the paddles closed on the puck. */
    private static final String LIFTED = "Lift:  between_moving  Grip:   closed_moving  " + INNER
            + "Lift:           maxed  Grip:          closed  " + INNER;

    /** Close on the puck, lift it, then as the keys after say. */
    private static List<KeysOnCue.Cue> graspAndLift(KeysOnCue.Cue... then) {
        List<KeysOnCue.Cue> cues = new ArrayList<>(List.of(
                new KeysOnCue.Cue("Grip:            open  " + INNER, 'c'),
                new KeysOnCue.Cue("Grip:          closed  " + INNER, 'u')));
        cues.addAll(List.of(then));
        return cues;
    }

    @Test
    void theKeysCloseOnThePuckLiftItLowerItAndOpenWithTheStateLoggedEveryCycle() throws Exception {
        try (ThreadedRun run = new ThreadedRun(world("p3dx-gripper.p"), 1, 600)) {
            Future<AriaExamplesTest.Ran> r1 = run.robot(() -> KeysOnCue.run(graspAndLift(
                    new KeysOnCue.Cue(LIFTED, 'd'),
                    new KeysOnCue.Cue(LIFTED, 'o'),
                    new KeysOnCue.Cue("Grip:         between  " + INNER + "Lift:           maxed  Grip:            open",
                            ESC)),
                    GripperExample::main, "r1", "127.0.0.1", String.valueOf(run.port())));
            AriaExamplesTest.Ran ran = r1.get(90, TimeUnit.SECONDS);
            run.await();
            String out = ran.out();
            assertEquals(0, ran.exit(), out);
            // as the C++ against a Pioneer: the query is answered after the connection, in the cycle
            assertTrue(out.contains("gripperExample: Connected to robot.\ngripperExample: GripperType=0\n"
                    + "Querying gripper type.\n"), out);
            assertTrue(out.contains("Gripper:  querried, using General IO.\n"), out);
            assertTrue(out.contains("Escape was pressed, program is exiting."), out);
            // the paddles close on the puck in 1.2 s (ARIA's word for them takes _moving from the
            // lift), the lift takes 3 s each way, the paddles open in 1.2 s: the same counts of cycles
            // as the C++ gripperExample logs through RoboSim's Pioneer port
            assertEquals(List.of("open", "12 between", "closed", "29 lifting", "closed", "29 lifting", "closed",
                    "12 between", "open"), shape(stateRuns(out)), stateRuns(out).toString());
            List<Snapshot.ObjectView> puck;
            synchronized (run.snapshots) {
                puck = run.snapshots.stream().map(f -> f.objects().get(0)).toList();
            }
            assertTrue(puck.stream().anyMatch(p -> "r1".equals(p.heldBy()) && p.lifted()), "held up at some step");
            Snapshot.ObjectView end = puck.get(puck.size() - 1);
            assertEquals(null, end.heldBy(), "let go");
            assertFalse(end.lifted());
            assertEquals(1500, end.x(), 1e-6, "put down where it stood");
            assertEquals(3000, end.y(), 1e-6);
        }
    }

    /** Each run of lines as its paddles' word, with the count for the timed motions. */
    private static List<String> shape(List<String> runs) {
        return runs.stream().map(r -> {
            String count = r.substring(0, r.indexOf(' '));
            if (r.contains("between_moving")) {
                return count + " lifting";
            }
            if (r.contains("Grip:         between")) {
                return count + " between";
            }
            return r.contains("Grip:          closed") ? "closed" : r.contains("Grip:            open") ? "open" : r;
        }).toList();
    }

    @Test
    void overThePioneerPortTheGripperQueryIsAnsweredAndThePuckIsLifted() throws Exception {
        try (PioneerRun run = new PioneerRun(WorldReader.read(world("p3dx-gripper.p")), false, code -> { })) {
            AriaExamplesTest.Ran ran = Background.supply("gripperExample", () -> KeysOnCue.run(
                    graspAndLift(new KeysOnCue.Cue(LIFTED, ESC)),
                    GripperExample::main, "-rh", "127.0.0.1", "-rrtp", String.valueOf(run.ports.portOf("r1"))))
                    .get(90, TimeUnit.SECONDS);
            String out = ran.out();
            assertEquals(0, ran.exit(), out);
            // the CONFIG reply says the robot has a gripper; its switches come in the SIPs' ANPORT
            assertTrue(out.contains("Gripper:  querried, using General IO.\n"), out);
            assertTrue(out.contains("Lift:           maxed  Grip:         between  " + INNER), out);
            Snapshot.ObjectView puck = run.env.sim.snapshot().objects().get(0);
            assertEquals("r1", puck.heldBy(), out);
            assertTrue(puck.lifted(), "lifted through the Pioneer port");
        }
    }

    @Test
    void aRobotWithoutAGripperIsQueriedAndLogsThatItHasNone() throws Exception {
        try (ThreadedRun run = new ThreadedRun(world("p3dx.p"), 1, 20)) {
            Future<AriaExamplesTest.Ran> r1 = run.robot(() -> AriaExamplesTest.runWithKeys("", GripperExample::main,
                    "r1", "127.0.0.1", String.valueOf(run.port())));
            AriaExamplesTest.Ran ran = r1.get(60, TimeUnit.SECONDS);
            run.await();
            String out = ran.out();
            // as ARIA's: the type is not known at the connection; the first cycle's answer says none
            assertEquals(0, ran.exit(), out);
            assertTrue(out.contains("Gripper:  querried, the robot has no gripper.\nThere is no gripper.\n"), out);
            assertFalse(out.contains("Lift:"), out);
        }
    }
}
