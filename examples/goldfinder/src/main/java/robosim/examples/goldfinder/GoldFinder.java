package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.List;
import robosim.hw.RobotThreads;

/**
 * Starts a team of {@link Gold} robots as threads of this JVM. (The {@code bin/robosim goldfinder}
 * command can also start each in a JVM of its own, running {@link Gold#main}.)
 */
public final class GoldFinder {
    private GoldFinder() {
    }

    /**
     * Starts robots {@code r1..rN} as threads (virtual ones where the JDK allows; see
     * {@link RobotThreads}); each searches until the run ends.
     *
     * @param host     the Environment's host
     * @param port     its robot port
     * @param robots   how many
     * @param cellSize the maze's cell size, mm
     * @param seed     the team's seed
     * @return the threads, started
     */
    public static List<Thread> start(String host, int port, int robots, double cellSize, long seed) {
        List<Thread> threads = new ArrayList<>();
        for (int k = 1; k <= robots; k++) {
            String name = "r" + k;
            Thread t = RobotThreads.unstarted("gold-" + name, () -> {
                Gold g = new Gold(name, host, port, cellSize, seed);
                if (g.blockingConnect()) {
                    g.search();
                    g.disconnect();
                }
            });
            t.start();
            threads.add(t);
        }
        return threads;
    }

    /**
     * Runs a team against a running Environment.
     *
     * @param args HOST PORT ROBOTS CELLSIZE [SEED]
     * @throws InterruptedException if interrupted
     */
    public static void main(String[] args) throws InterruptedException {
        if (args.length < 4) {
            throw new IllegalArgumentException("usage: GoldFinder HOST PORT ROBOTS CELLSIZE [SEED]");
        }
        for (Thread t : start(args[0], Integer.parseInt(args[1]), Integer.parseInt(args[2]),
                Double.parseDouble(args[3]), args.length > 4 ? Long.parseLong(args[4]) : 1)) {
            t.join();
        }
    }
}
