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
 * compare the two; a {@link RobotRuntime} reads it when it is made ({@link RuntimeChoices}), or is
 * told. Which kind a thread is never changes what a robot program sees: a step still waits for
 * every robot's code to yield.
 */
public final class RobotThreads {
    /** The system property that keeps platform threads when it is {@code platform}. */
    public static final String PROPERTY = "robosim.threads";
    /** The first JDK whose virtual threads unmount in {@code Object.wait}, which {@link StepGate} uses. */
    static final int FIRST_UNPINNED_WAIT_JDK = 24;

    /** {@code Thread.ofVirtual()}, {@code Builder.name(String)} and {@code Builder.unstarted(Runnable)}. */
    private record VirtualThreads(Method ofVirtual, Method name, Method unstarted) {
        /** @return them, or null where the JDK's virtual threads do not suit robots (before JDK 24) */
        static VirtualThreads find() {
            if (Runtime.version().feature() < FIRST_UNPINNED_WAIT_JDK) {
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

    /**
     * @return whether robot threads are virtual in this JVM: the JDK allows it and the system
     *         property {@value #PROPERTY} does not say {@code platform}
     */
    public static boolean virtual() {
        return VIRTUAL != null && !platformConfigured();
    }

    /** @return whether the system property {@value #PROPERTY} says {@code platform} */
    static boolean platformConfigured() {
        return "platform".equals(System.getProperty(PROPERTY));
    }

    /**
     * Makes a robot thread, not yet started: virtual where the JDK allows and {@value #PROPERTY}
     * does not say {@code platform}, else a platform daemon thread.
     *
     * @param threadName the thread's name
     * @param task       what it runs
     * @return the thread
     */
    public static Thread unstarted(String threadName, Runnable task) {
        return unstarted(threadName, task, virtual());
    }

    /**
     * Makes a robot thread, not yet started, of the kind asked for where the JDK allows it.
     *
     * @param threadName the thread's name
     * @param task       what it runs
     * @param virtual    whether it is to be virtual (JDK 24 and newer only); else a platform daemon thread
     * @return the thread
     */
    static Thread unstarted(String threadName, Runnable task, boolean virtual) {
        if (virtual && VIRTUAL != null) {
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
