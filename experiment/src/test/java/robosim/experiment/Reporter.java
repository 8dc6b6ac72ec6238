package robosim.experiment;

import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * A test program: each robot reports how many times it has looked around (r1 ten, r2 twenty), and
 * r1 then ends the run.
 */
public final class Reporter {
    private Reporter() {
    }

    /** @param args robot, host, port */
    public static void main(String[] args) {
        ArRobot robot = new ArRobot(args[0], args[1], Integer.parseInt(args[2]), "p3dx");
        if (!robot.blockingConnect()) {
            throw new IllegalStateException("could not connect: " + robot.getConnectionError());
        }
        int looks = args[0].equals("r1") ? 10 : 20;
        for (int i = 1; i <= looks; i++) {
            ArUtil.sleep(100);
            robot.reportMetric("looks", i);
        }
        if (args[0].equals("r1")) {
            robot.endRun("looked " + looks + " times");
        }
        robot.waitForRunExit();
        robot.disconnect();
    }
}
