package robosim.aria;

import robosim.hw.AbstractRobot;
import robosim.hw.RobotRuntime;

/**
 * Where {@link ArTime} reads "now": simulated time, never the wall clock, so that a program's timing
 * is the same on every run. A thread of a robot's code reads its robot's time (for an
 * {@link ArRobot}, the time of the state its cycle delivered); any other thread reads the time of the
 * latest state a robot of the default {@link RobotRuntime} received (a robot's thread whose robot is
 * not connected, its runtime's). Robots share the Environment's lockstep steps, so every robot of a
 * run sees the same time. Before any state has arrived the time is 0.
 */
final class SimulatedClock {
    private SimulatedClock() {
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
        RobotRuntime runtime = robot != null ? robot.getRuntime() : null;
        if (runtime != null) {
            return runtime.latestTimeMs();
        }
        return RobotRuntime.currentDefault().map(RobotRuntime::latestTimeMs).orElse(0L);
    }
}
