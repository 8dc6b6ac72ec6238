package robosim.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.StringJoiner;
import java.util.function.LongSupplier;

/**
 * A run cut into windows of {@code every} steps, so a long run shows whether it slows down: for
 * each window the wall-clock time, this JVM's CPU time (all its threads, the JIT's and the garbage
 * collector's included) and the heap its threads allocated. Marks are taken at the first step seen
 * at or past each multiple of {@code every}, and at the start and end of the run. Cheap when no
 * mark is due; one thread at a time.
 *
 * <p>Allocation is summed over the JVM's live platform threads
 * ({@code com.sun.management.ThreadMXBean.getThreadAllocatedBytes}); a virtual thread's allocation
 * counts on its carrier, and a thread that ended takes its count with it, so it is an approximation
 * where threads come and go. A figure this JVM does not give is -1. Where the run can tell (the core
 * alone, on the thread that steps it), each mark also counts the robots stalled then.
 */
public final class StepWindows {
    /** How a client JVM's line of marks starts in its log. */
    static final String CLIENT_MARK = "bench-windows";

    /**
     * Where a run stood when a mark was taken.
     *
     * @param step           the step reached
     * @param nanos          {@link System#nanoTime()}
     * @param cpuNanos       this JVM's CPU time so far, or -1
     * @param allocatedBytes the heap its threads have allocated so far, or -1
     * @param stalled        robots stalled then, or -1 if unknown
     */
    record Mark(long step, long nanos, long cpuNanos, long allocatedBytes, long stalled) {
        String encode() {
            return step + ":" + nanos + ":" + cpuNanos + ":" + allocatedBytes + ":" + stalled;
        }

        static Mark decode(String s) {
            String[] p = s.split(":");
            if (p.length != 5) {
                throw new IllegalArgumentException(s + " was supplied for a window mark: it must be"
                        + " step:nanos:cpu:allocated:stalled");
            }
            return new Mark(Long.parseLong(p[0]), Long.parseLong(p[1]), Long.parseLong(p[2]), Long.parseLong(p[3]),
                    Long.parseLong(p[4]));
        }
    }

    /**
     * One window of a run.
     *
     * @param from           the step it starts after
     * @param to             the step it ends with
     * @param seconds        wall-clock time
     * @param cpuNanos       the JVM's CPU time in it, or -1 if unknown
     * @param allocatedBytes heap allocated in it, or -1 if unknown
     * @param stalled        robots stalled at its end, or -1 if unknown
     */
    public record Window(long from, long to, double seconds, long cpuNanos, long allocatedBytes, long stalled) {
        /** @return steps per second */
        public double stepsPerSecond() {
            return (to - from) / seconds;
        }

        /** @return the JVM's CPU time per step, µs, or -1 if unknown */
        public double cpuMicrosPerStep() {
            return cpuNanos < 0 ? -1 : cpuNanos / 1e3 / (to - from);
        }

        /** @return the heap allocated per step, KiB, or -1 if unknown */
        public double allocatedKibPerStep() {
            return allocatedBytes < 0 ? -1 : allocatedBytes / 1024.0 / (to - from);
        }
    }

    private final long every;
    private final LongSupplier clock;
    private final LongSupplier cpu;
    private final LongSupplier allocated;
    private final LongSupplier stalled;
    private final List<Mark> marks = new ArrayList<>();
    private long next;

    /**
     * Windows of this JVM.
     *
     * @param every steps per window, at least 1
     */
    public StepWindows(long every) {
        this(every, () -> -1);
    }

    /**
     * Windows of this JVM that also count the robots stalled at each mark.
     *
     * @param every   steps per window, at least 1
     * @param stalled robots stalled now, asked on the thread that marks, or -1 if unknown
     */
    public StepWindows(long every, LongSupplier stalled) {
        this(every, System::nanoTime, StepWindows::processCpuNanos, StepWindows::allocatedBytes, stalled);
    }

    /**
     * @param every     steps per window, at least 1
     * @param clock     nanoseconds
     * @param cpu       CPU time so far, ns, or -1
     * @param allocated heap allocated so far, bytes, or -1
     * @param stalled   robots stalled now, or -1
     */
    StepWindows(long every, LongSupplier clock, LongSupplier cpu, LongSupplier allocated, LongSupplier stalled) {
        if (every < 1) {
            throw new IllegalArgumentException(every + " was supplied for steps per window: it must be at least 1");
        }
        this.every = every;
        this.clock = clock;
        this.cpu = cpu;
        this.allocated = allocated;
        this.stalled = stalled;
    }

    /**
     * Takes a mark if one is due: the first at any step (the run's start), then at the first step at
     * or past each multiple of the window.
     *
     * @param step the step the run has reached
     */
    public synchronized void at(long step) {
        if (marks.isEmpty() || step >= next) {
            mark(step);
        }
    }

    /**
     * Takes a mark whether or not one is due, such as at the end of the run, unless one was taken at
     * this step.
     *
     * @param step the step the run has reached
     */
    public synchronized void end(long step) {
        if (marks.isEmpty() || marks.get(marks.size() - 1).step() != step) {
            mark(step);
        }
    }

    private void mark(long step) {
        marks.add(new Mark(step, clock.getAsLong(), cpu.getAsLong(), allocated.getAsLong(), stalled.getAsLong()));
        next = (step / every + 1) * every;
    }

    /** @return the windows between the marks taken, in order */
    public synchronized List<Window> windows() {
        return windows(marks);
    }

    static List<Window> windows(List<Mark> marks) {
        List<Window> out = new ArrayList<>();
        for (int i = 1; i < marks.size(); i++) {
            Mark a = marks.get(i - 1);
            Mark b = marks.get(i);
            if (b.step() > a.step()) {
                out.add(new Window(a.step(), b.step(), (b.nanos() - a.nanos()) / 1e9, difference(a.cpuNanos(), b.cpuNanos()),
                        difference(a.allocatedBytes(), b.allocatedBytes()), b.stalled()));
            }
        }
        return out;
    }

    private static long difference(long a, long b) {
        return a < 0 || b < 0 ? -1 : b - a;
    }

    /** @return the line a client JVM prints its marks on: {@value #CLIENT_MARK} and the marks */
    public synchronized String clientLine() {
        StringJoiner j = new StringJoiner(",", CLIENT_MARK + " ", "");
        marks.forEach(m -> j.add(m.encode()));
        return j.toString();
    }

    /**
     * Finds a client JVM's windows in its log.
     *
     * @param lines the log's lines
     * @return the windows on its last {@value #CLIENT_MARK} line, or empty if it has none or it cannot
     *         be read
     */
    static Optional<List<Window>> clientWindows(List<String> lines) {
        for (int i = lines.size() - 1; i >= 0; i--) {
            String line = lines.get(i).strip();
            if (line.startsWith(CLIENT_MARK + " ") || line.equals(CLIENT_MARK)) {
                List<Mark> marks = new ArrayList<>();
                try {
                    for (String m : line.substring(CLIENT_MARK.length()).strip().split(",")) {
                        if (!m.isEmpty()) {
                            marks.add(Mark.decode(m));
                        }
                    }
                } catch (IllegalArgumentException e) {
                    return Optional.empty();
                }
                return Optional.of(windows(marks));
            }
        }
        return Optional.empty();
    }

    /** @return this JVM's CPU time so far, ns, or -1 if it does not tell */
    static long processCpuNanos() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() : -1;
    }

    /** @return the heap this JVM's live platform threads have allocated so far, bytes, or -1 if it does not tell */
    static long allocatedBytes() {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        if (!(threads instanceof com.sun.management.ThreadMXBean sun) || !sun.isThreadAllocatedMemoryEnabled()) {
            return -1;
        }
        long sum = 0;
        for (long bytes : sun.getThreadAllocatedBytes(threads.getAllThreadIds())) {
            sum += Math.max(0, bytes);
        }
        return sum;
    }
}
