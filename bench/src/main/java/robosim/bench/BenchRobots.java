package robosim.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntUnaryOperator;
import robosim.aria.ArRobot;
import robosim.aria.ArUtil;

/**
 * The benchmark's client JVM: robots {@code b0..b(N-1)}, one thread each, each reading its 16
 * sonars and setting its speed every step until the Environment ends the run.
 */
public final class BenchRobots {
    private BenchRobots() {
    }

    /**
     * @param args HOST PORT COUNT PARAMFILE
     * @throws InterruptedException if interrupted
     */
    public static void main(String[] args) throws InterruptedException {
        String host = args[0];
        int port = Integer.parseInt(args[1]);
        int count = Integer.parseInt(args[2]);
        String params = args[3];
        List<Thread> threads = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            String name = "b" + k;
            Thread t = new Thread(() -> drive(new ArRobot(name, host, port, params)), name);
            threads.add(t);
            t.start();
        }
        for (Thread t : threads) {
            t.join();
        }
    }

    private static void drive(ArRobot robot) {
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(robot.getName() + ": " + robot.getConnectionError());
        }
        while (robot.isConnected()) {
            boolean blocked = blocked(robot::getSonarRange, robot.getNumSonar());
            robot.setVel(blocked ? 0 : 300);
            robot.setRotVel(blocked ? 30 : 0);
            ArUtil.sleep(100);
        }
    }

    /**
     * The benchmark robots' one decision, shared with {@link CoreBench} so both measure the same
     * logic: blocked when the nearest sonar echo is under 600 mm and comes from a front sonar (0–7).
     *
     * @param range the range of sonar i, mm
     * @param count how many sonars
     * @return whether to stop and turn (30 deg/s) instead of driving (300 mm/s)
     */
    static boolean blocked(IntUnaryOperator range, int count) {
        int nearest = Integer.MAX_VALUE;
        int nearestIndex = 0;
        for (int i = 0; i < count; i++) {
            int r = range.applyAsInt(i);
            if (r < nearest) {
                nearest = r;
                nearestIndex = i;
            }
        }
        return nearest < 600 && nearestIndex <= 7;
    }
}
