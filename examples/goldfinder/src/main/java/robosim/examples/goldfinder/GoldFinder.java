package robosim.examples.goldfinder;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Logger;
import robosim.hw.RobotThreads;

/**
 * GoldFinder's robot application, run as the original's: {@code java
 * robosim.examples.goldfinder.GoldFinder robotName host port} connects one {@link Gold} robot;
 * start one per robot of the world, each in its own terminal (or JVM). {@link #start} instead
 * starts a whole team as threads of this JVM, as {@code bin/robosim goldfinder} does.
 */
public final class GoldFinder {
    private static final Logger LOG = Logger.getLogger(GoldFinder.class.getName());

    private GoldFinder() {
    }

    /**
     * Starts robots {@code r1..rN} as threads (virtual ones where the JDK allows; see
     * {@link RobotThreads}); each searches until the run ends. The cell size and the seed of their
     * tie-breaks come from the world and the run, through the Environment's welcome.
     *
     * @param host   the Environment's host
     * @param port   its robot port
     * @param robots how many
     * @return the threads, started
     */
    public static List<Thread> start(String host, int port, int robots) {
        List<Thread> threads = new ArrayList<>();
        for (int k = 1; k <= robots; k++) {
            String name = "r" + k;
            Thread t = RobotThreads.unstarted("gold-" + name, () -> {
                Gold g = new Gold(name, host, port);
                if (g.blockingConnect()) {
                    try {
                        g.search();
                    } catch (IllegalStateException e) {
                        LOG.severe(e.getMessage());
                    }
                    g.disconnect();
                }
            });
            t.start();
            threads.add(t);
        }
        return threads;
    }

    /**
     * Runs one Gold robot against a running Environment, the original's way.
     *
     * @param args robotName host port
     */
    public static void main(String[] args) {
        Gold.run(args, "GoldFinder");
    }
}
