package robosim.hw;

import java.lang.reflect.Method;

/**
 * Makes the threads that run robots: a {@link HardwareSimulator}'s link thread, and the threads a
 * program starts for robot code (GoldFinder's team, the benchmark's robots). On a JDK that has
 * virtual threads whose {@code Object.wait} does not pin their carrier (JDK 24 and newer) they are
 * virtual: a step's hand-off between a robot's link and its code then costs well under a
 * microsecond instead of a platform thread's wake-up (tens of microseconds across cores). On
 * JDK 17 to 23 they are platform daemon threads, as before.
 *
 * <p>The system property {@code robosim.threads=platform} keeps platform threads on any JDK, to
 * compare the two. Which kind a thread is never changes what a robot program sees: a step still
 * waits for every robot's code to yield.
 */
public final class RobotThreads {
    /** The first JDK whose virtual threads unmount in {@code Object.wait}, which {@link StepGate} uses. */
    static final int FIRST_UNPINNED_WAIT_JDK = 24;

    /** {@code Thread.ofVirtual()}, {@code Builder.name(String)} and {@code Builder.unstarted(Runnable)}. */
    private record VirtualThreads(Method ofVirtual, Method name, Method unstarted) {
        /** @return them, or null where robot threads are platform threads */
        static VirtualThreads find() {
            if (Runtime.version().feature() < FIRST_UNPINNED_WAIT_JDK
                    || "platform".equals(System.getProperty("robosim.threads"))) {
                return null;
            }
            try {
                Class<?> builder = Class.forName("java.lang.Thread$Builder");
                return new VirtualThreads(Thread.class.getMethod("ofVirtual"),
                        builder.getMethod("name", String.class), builder.getMethod("unstarted", Runnable.class));
            } catch (ReflectiveOperationException e) {
                return null;
            }
        }

        Thread unstarted(String threadName, Runnable task) throws ReflectiveOperationException {
            return (Thread) unstarted.invoke(name.invoke(ofVirtual.invoke(null), threadName), task);
        }
    }

    private static final VirtualThreads VIRTUAL = VirtualThreads.find();

    private RobotThreads() {
    }

    /** @return whether robot threads are virtual in this JVM */
    public static boolean virtual() {
        return VIRTUAL != null;
    }

    /**
     * Makes a robot thread, not yet started: virtual where the JDK allows, else a platform daemon
     * thread.
     *
     * @param threadName the thread's name
     * @param task       what it runs
     * @return the thread
     */
    public static Thread unstarted(String threadName, Runnable task) {
        if (VIRTUAL != null) {
            try {
                return VIRTUAL.unstarted(threadName, task);
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException("cannot make virtual thread " + threadName, e);
            }
        }
        Thread t = new Thread(task, threadName);
        t.setDaemon(true);
        return t;
    }
}
