package robosim.hw;

import java.util.Set;

/**
 * A runtime's watchdog thread ({@code hw-watchdog-<runtime>}), from its first robot to its last:
 * every {@link HardwareSimulator#WATCH_MS} ms it looks after each robot (see
 * {@link HardwareSimulator#watch()}) and sends what the runtime's shared links have collected when
 * some of their robots are late.
 */
final class Watchdog {
    private final Thread thread;
    private volatile boolean stopped;

    private Watchdog(String runtime, Set<HardwareSimulator> robots, SharedLinks links) {
        thread = new Thread(() -> run(robots, links), "hw-watchdog-" + runtime);
        thread.setDaemon(true);
    }

    /**
     * Starts a watchdog.
     *
     * @param runtime the runtime's name, for the thread's
     * @param robots  the robots to look after, as they come and go
     * @param links   the shared links whose late robots it sends for
     * @return the watchdog, running
     */
    static Watchdog start(String runtime, Set<HardwareSimulator> robots, SharedLinks links) {
        Watchdog w = new Watchdog(runtime, robots, links);
        w.thread.start();
        return w;
    }

    private void run(Set<HardwareSimulator> robots, SharedLinks links) {
        while (!stopped) {
            for (HardwareSimulator hw : robots) {
                hw.watch();
            }
            links.sendLingering();
            try {
                Thread.sleep(HardwareSimulator.WATCH_MS);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    /** Stops the thread; it ends within a watch period, or at once if it is asleep. */
    void stop() {
        stopped = true;
        thread.interrupt();
    }
}
