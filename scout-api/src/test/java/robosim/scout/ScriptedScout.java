package robosim.scout;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.Bumpers;
import robosim.protocol.Command;
import robosim.protocol.HeatReading;
import robosim.protocol.LaserReading;
import robosim.protocol.RobotState;
import robosim.protocol.RobotStates;
import robosim.protocol.SonarReading;
import robosim.params.RobotParametersReader;

/**
 * A Scout with no Environment: it counts as connected, records what it would send, and each time
 * its code yields it is handed the next scripted state (or, when the script is used up, the last
 * state again one step later).
 */
final class ScriptedScout extends Scout {
    static final int STEP_MS = 100;
    final List<Command> sent = new ArrayList<>();
    private final Deque<RobotState> script = new ArrayDeque<>();
    private boolean connected = true;

    ScriptedScout() {
        super("s1", "127.0.0.1", 5000, RobotParametersReader.read(scoutFile()));
    }

    static Path scoutFile() {
        Path p = Path.of(System.getProperty("robosim.root", "")).toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        return p.resolve("testLoadFiles/robots/scout.p");
    }

    /** A state at step {@code step} (time step · 100 ms). */
    static RobotState at(long step, double x, double y, double th, double left, double right, int[] sonar,
                         int bumpers) {
        return RobotStates.of(step, step * STEP_MS, x, y, th, (left + right) / 2, 0, left, right, false, sonar, 0,
                new int[0], null, List.of(), List.of(), bumpers);
    }

    /** A state at rest at the origin with sonar readings. */
    static RobotState sonarAt(long step, int[] sonar) {
        return at(step, 0, 0, 0, 0, 0, sonar, 0);
    }

    /** @param states states handed to the robot, in order, as its code yields */
    void queue(RobotState... states) {
        script.addAll(List.of(states));
    }

    /** Hands the robot one state now, as the hardware thread would. */
    void deliver(RobotState s) {
        responded(new RobotSensorResponse(s));
    }

    void disconnectNow() {
        connected = false;
    }

    @Override
    public boolean isConnected() {
        return connected;
    }

    @Override
    protected void request(Command command) {
        sent.add(command);
    }

    @Override
    public void sleepSimulated(long ms) {
        long wake = state().timeMs() + Math.max(ms, 1);
        while (state().timeMs() < wake) {
            RobotState next = script.poll();
            if (next == null) {
                RobotState s = state();
                next = RobotStates.of(s.step() + 1, s.timeMs() + STEP_MS, s.x(), s.y(), s.th(), s.vel(),
                        s.rotVel(), s.leftVel(), s.rightVel(), s.stalled(), s.get(SonarReading.PART).ranges(),
                        s.collisions(), s.get(LaserReading.PART).ranges(), s.get(HeatReading.PART), List.of(),
                        List.of(), s.get(Bumpers.PART).sectors());
            }
            deliver(next);
        }
    }

    /** @return the step of the latest state handed to the robot */
    long getStateStep() {
        return state().step();
    }
}
