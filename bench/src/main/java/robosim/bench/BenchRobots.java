package robosim.bench;

import java.lang.management.ManagementFactory;
import java.lang.ref.Reference;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntUnaryOperator;
import java.util.logging.Logger;
import robosim.aria.ArRobot;
import robosim.aria.ArSick;
import robosim.aria.ArUtil;
import robosim.hw.RobotThreads;

/**
 * The benchmark's client JVM: robots {@code b<first>..b<first+count-1>}, one thread each, each
 * reading its 16 sonars (and, with {@link BenchSensors#LASER}, its SICK laser's scan) and setting
 * its speed every step until the Environment ends the run. If any robot fails, the JVM exits with
 * status 1 at once, so the benchmark learns of it without waiting for a timeout. When every robot has
 * been disconnected, and before they are let go, it prints its memory ({@link JvmMemory#figures}) on
 * one line of its standard output, and its windows ({@link StepWindows}) on another if asked, which
 * {@link StepRateBench} reads from its log.
 */
public final class BenchRobots {
    private static final Logger LOG = Logger.getLogger(BenchRobots.class.getName());
    /** Half the angle ahead in which the laser's nearest beam is looked for, degrees. */
    private static final double AHEAD_DEGREES = 20;
    /** Nearer than this ahead, a robot stops and turns, mm. */
    private static final int NEAR = 600;

    private BenchRobots() {
    }

    /**
     * The robots one client JVM runs: {@code b<first>} and the {@code count - 1} after it.
     *
     * @param first the number of the first robot
     * @param count how many robots, at least 1
     */
    public record Share(int first, int count) {
        /** Checks the values. */
        public Share {
            if (first < 0 || count < 1) {
                throw new IllegalArgumentException("robots " + first + " (" + count
                        + " of them) were supplied for a client's share: it starts at 0 or more and holds at least 1");
            }
        }
    }

    /**
     * Spreads robots {@code b0..b(robots-1)} over client JVMs as evenly as possible, in order: the
     * first {@code robots mod clients} clients get one robot more than the others. No client gets
     * none: there are {@code min(robots, clients)} shares.
     *
     * @param robots  how many robots, at least 1
     * @param clients how many client JVMs at most, at least 1
     * @return each client's share, in robot order
     */
    public static List<Share> split(int robots, int clients) {
        if (robots < 1) {
            throw new IllegalArgumentException(robots + " was supplied for robots: it must be at least 1");
        }
        if (clients < 1) {
            throw new IllegalArgumentException(clients + " was supplied for clients: it must be at least 1");
        }
        int k = Math.min(robots, clients);
        List<Share> shares = new ArrayList<>(k);
        int first = 0;
        for (int c = 0; c < k; c++) {
            int count = robots / k + (c < robots % k ? 1 : 0);
            shares.add(new Share(first, count));
            first += count;
        }
        return shares;
    }

    /**
     * Runs one client JVM's robots.
     *
     * @param args HOST PORT FIRST COUNT PARAMFILE [SENSORS [HEAP_EVERY [WINDOW]]]: SENSORS is
     *             {@code sonar} (the default) or {@code laser}; HEAP_EVERY, the steps between samples of
     *             the heap after the last garbage collection, taken by the first robot (0, the default,
     *             for none); WINDOW, the steps per window of this JVM's CPU time and allocation, marked
     *             by the first robot (0, the default, for none)
     * @throws InterruptedException if interrupted
     */
    public static void main(String[] args) throws InterruptedException {
        if (args.length < 5) {
            throw new IllegalArgumentException("usage: BenchRobots HOST PORT FIRST COUNT PARAMFILE [sonar|laser [HEAP_EVERY [WINDOW]]]");
        }
        long mainMs = ManagementFactory.getRuntimeMXBean().getUptime();
        String host = args[0];
        int port = Integer.parseInt(args[1]);
        Share share = new Share(Integer.parseInt(args[2]), Integer.parseInt(args[3]));
        String params = args[4];
        BenchSensors sensors = args.length > 5 ? BenchSensors.named(args[5]).orElseThrow(
                () -> new IllegalArgumentException(args[5] + " was supplied for SENSORS: sensors are sonar or laser"))
                : BenchSensors.SONAR;
        long heapEvery = args.length > 6 ? Long.parseLong(args[6]) : 0;
        JvmMemory.Sampler samples = heapEvery > 0 ? new JvmMemory.Sampler(heapEvery) : null;
        long window = args.length > 7 ? Long.parseLong(args[7]) : 0;
        StepWindows windows = window > 0 ? new StepWindows(window) : null;
        CountDownLatch disconnected = new CountDownLatch(share.count());
        CountDownLatch measured = new CountDownLatch(1);
        AtomicInteger connected = new AtomicInteger();
        Thread.UncaughtExceptionHandler failed = (thread, e) -> {
            LOG.severe("robot " + thread.getName() + " failed: " + e);
            System.exit(1);
        };
        List<Thread> threads = new ArrayList<>();
        for (int k = share.first(); k < share.first() + share.count(); k++) {
            String name = "b" + k;
            JvmMemory.Sampler sampler = k == share.first() ? samples : null;
            StepWindows marks = k == share.first() ? windows : null;
            Thread t = RobotThreads.unstarted(name, () -> {
                ArRobot robot = drive(name, host, port, params, sensors, sampler, marks, () -> {
                    if (connected.incrementAndGet() == share.count()) {
                        LOG.info("all " + share.count() + " robots connected " + ManagementFactory.getRuntimeMXBean().getUptime()
                                + " ms after this JVM started (main began at " + mainMs + " ms), " + cpuMs()
                                + " ms of CPU used by this JVM");
                    }
                });
                if (sampler != null) {
                    sampler.add(robot.getCounter());
                }
                if (marks != null) {
                    marks.end(robot.getCounter());
                }
                // held until the memory is measured, so the figures count every robot
                disconnected.countDown();
                awaitUninterruptibly(measured);
                Reference.reachabilityFence(robot);
            });
            t.setUncaughtExceptionHandler(failed);
            threads.add(t);
        }
        for (Thread t : threads) {
            t.start();
        }
        disconnected.await();
        if (windows != null) {
            System.out.println(windows.clientLine());
        }
        System.out.println(JvmMemory.clientLine(JvmMemory.figures(samples)));
        System.out.flush();
        measured.countDown();
        for (Thread t : threads) {
            t.join();
        }
    }

    private static void awaitUninterruptibly(CountDownLatch latch) {
        boolean interrupted = false;
        while (true) {
            try {
                latch.await();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /** @return the CPU time this JVM has used, ms, or -1 if the JVM does not tell */
    private static long cpuMs() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() / 1_000_000 : -1;
    }

    /**
     * Runs one robot until the Environment ends the run.
     *
     * @param sampler samples the heap at this robot's steps, or {@code null}
     * @param windows marks this JVM's windows at this robot's steps, or {@code null}
     * @return the robot, disconnected
     */
    private static ArRobot drive(String name, String host, int port, String params, BenchSensors sensors,
                                 JvmMemory.Sampler sampler, StepWindows windows, Runnable welcomed) {
        return drive(new ArRobot(name, host, port, params), sensors, sampler, windows, welcomed);
    }

    /**
     * Runs one robot, made and given its runtime, until the Environment ends the run.
     *
     * @param robot   the robot, not yet connected
     * @param sensors what it reads
     * @param sampler samples the heap at this robot's steps, or {@code null}
     * @param windows marks this JVM's windows at this robot's steps, or {@code null}
     * @param welcomed run once the robot (and its laser) is connected
     * @return the robot, disconnected
     */
    static ArRobot drive(ArRobot robot, BenchSensors sensors, JvmMemory.Sampler sampler, StepWindows windows,
                         Runnable welcomed) {
        ArSick laser = null;
        if (sensors.laser()) {
            laser = new ArSick();
            laser.setMaxRange(BenchSensors.LASER_MAX_RANGE);
            laser.setIncrement(BenchSensors.LASER_INCREMENT);
            robot.addRangeDevice(laser);
        }
        if (!robot.blockingConnect()) {
            throw new IllegalStateException(robot.getName() + ": " + robot.getConnectionError());
        }
        robot.enableMotors(); // a Pioneer's motors are disabled when its program connects, as in ARIA
        if (laser != null && !laser.blockingConnect()) {
            throw new IllegalStateException(robot.getName() + "'s laser: " + laser.getConnectionError());
        }
        welcomed.run();
        int[] none = new int[0];
        while (robot.isConnected()) {
            boolean blocked = blocked(robot::getSonarRange, robot.getNumSonar(), laser == null ? none : laser.getRawScan());
            robot.setVel(blocked ? 0 : 300);
            robot.setRotVel(blocked ? 30 : 0);
            ArUtil.sleep(100);
            if (sampler != null) {
                sampler.at(robot.getCounter());
            }
            if (windows != null && robot.getCounter() > 0) {
                windows.at(robot.getCounter());
            }
        }
        return robot;
    }

    /**
     * The benchmark robots' one decision, shared with {@link CoreBench} so both measure the same
     * logic: blocked when the nearest sonar echo is under 600 mm and comes from a front sonar
     * (0–7), or when the laser's nearest beam within 20° of straight ahead is under 600 mm.
     *
     * @param range the range of sonar i, mm
     * @param count how many sonars
     * @param laser the laser's latest scan, mm, from its right to its left; empty without a laser
     * @return whether to stop and turn (30 deg/s) instead of driving (300 mm/s)
     */
    static boolean blocked(IntUnaryOperator range, int count, int[] laser) {
        int nearest = Integer.MAX_VALUE;
        int nearestIndex = 0;
        for (int i = 0; i < count; i++) {
            int r = range.applyAsInt(i);
            if (r < nearest) {
                nearest = r;
                nearestIndex = i;
            }
        }
        return nearest < NEAR && nearestIndex <= 7 || nearestAhead(laser) < NEAR;
    }

    /**
     * @param scan a laser scan over 180°, from right to left; may be empty
     * @return the nearest range within 20° of straight ahead, mm, or {@code Integer.MAX_VALUE} for an
     *         empty scan
     */
    static int nearestAhead(int[] scan) {
        if (scan.length == 0) {
            return Integer.MAX_VALUE;
        }
        int centre = (scan.length - 1) / 2;
        int half = (int) Math.round(AHEAD_DEGREES * (scan.length - 1) / 180.0);
        int nearest = Integer.MAX_VALUE;
        for (int i = Math.max(0, centre - half); i <= Math.min(scan.length - 1, centre + half); i++) {
            nearest = Math.min(nearest, scan[i]);
        }
        return nearest;
    }
}
