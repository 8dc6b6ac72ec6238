package robosim.aria;

import robosim.hw.AbstractRobot;

/**
 * Where {@link ArTime} reads "now": simulated time, never the wall clock, so that a program's timing
 * is the same on every run. A thread of a robot's code reads its robot's time (for an
 * {@link ArRobot}, the time of the state its cycle delivered); any other thread reads the time of the
 * latest state any {@link ArRobot} in this JVM received. Robots share the Environment's lockstep
 * steps, so every robot in a JVM sees the same time. Before any state has arrived the time is 0.
 */
final class SimulatedClock {
    private static volatile long latestMs;

    private SimulatedClock() {
    }

    /** @param timeMs the simulated time of a state an {@link ArRobot}'s cycle received */
    static void stateArrived(long timeMs) {
        latestMs = timeMs;
    }

    /** @return the simulated time, ms */
    static long nowMs() {
        AbstractRobot robot = AbstractRobot.current();
        if (robot instanceof ArRobot ar && ar.currentState() != null) {
            return ar.currentState().timeMs();
        }
        if (robot != null && robot.isConnected()) {
            return robot.getSimTimeMs();
        }
        return latestMs;
    }
}
