package robosim.bench;

import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.MemoryUsage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Set;
import java.util.StringJoiner;
import java.util.function.LongSupplier;

/**
 * A JVM's memory as the benchmark reports it, as {@code key=value} figures in MiB: its resident set
 * (from {@code /proc/<pid>/status}, Linux only) and its heap after garbage collections.
 *
 * <p>"Heap after the last GC" is the heap pools' usage that the JVM recorded at the end of its most
 * recent collection ({@code com.sun.management.GarbageCollectorMXBean.getLastGcInfo()}, each pool
 * from the latest collection that reports it), forcing none. It is not
 * {@code MemoryPoolMXBean.getCollectionUsage()}: G1 updates the old generation's collection usage
 * only after mixed and full collections, so after young ones that sum leaves out what they promoted.
 */
public final class JvmMemory {
    /** How a client JVM's line of figures starts in its log. */
    static final String CLIENT_MARK = "bench-memory";
    /** What a figure this machine does not give says instead of a number. */
    static final String UNAVAILABLE = "unavailable";
    private static final double MIB = 1024.0 * 1024.0;

    private JvmMemory() {
    }

    /**
     * The resident set of a process.
     *
     * @param rssKb its resident set now ({@code VmRSS}), KiB
     * @param hwmKb the largest it has been ({@code VmHWM}), KiB
     */
    public record Resident(long rssKb, long hwmKb) {
    }

    /**
     * One JVM's figures for one run.
     *
     * @param jvm     which JVM: {@code env} or {@code client0}, {@code client1}...
     * @param figures its {@code key=value} figures, in the order printed
     */
    public record Report(String jvm, Map<String, String> figures) {
        /** Copies the figures. */
        public Report {
            figures = Collections.unmodifiableMap(new LinkedHashMap<>(figures));
        }
    }

    /**
     * Reads a process's resident set.
     *
     * @param status its status file, such as {@code /proc/self/status}
     * @return its resident set, or empty where there is no such file or it does not say (not Linux)
     */
    public static Optional<Resident> resident(Path status) {
        try {
            return parseStatus(Files.readString(status));
        } catch (IOException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /**
     * @param text a {@code /proc/<pid>/status} file's text
     * @return its {@code VmRSS} and {@code VmHWM}, or empty if either is missing
     */
    static Optional<Resident> parseStatus(String text) {
        OptionalLong rss = statusKb(text, "VmRSS");
        OptionalLong hwm = statusKb(text, "VmHWM");
        return rss.isPresent() && hwm.isPresent() ? Optional.of(new Resident(rss.getAsLong(), hwm.getAsLong()))
                : Optional.empty();
    }

    /**
     * @param text a {@code /proc/<pid>/status} file's text: lines such as {@code VmRSS:\t  123456 kB}
     * @param key  the field, such as {@code VmRSS}
     * @return its value in KiB, or empty if the text has no such field or its value is not in kB
     */
    static OptionalLong statusKb(String text, String key) {
        for (String line : text.split("\n")) {
            int colon = line.indexOf(':');
            if (colon < 0 || !line.substring(0, colon).equals(key)) {
                continue;
            }
            String[] parts = line.substring(colon + 1).strip().split("\\s+");
            if (parts.length != 2 || !parts[1].equalsIgnoreCase("kB")) {
                return OptionalLong.empty();
            }
            try {
                return OptionalLong.of(Long.parseLong(parts[0]));
            } catch (NumberFormatException e) {
                return OptionalLong.empty();
            }
        }
        return OptionalLong.empty();
    }

    /**
     * @return the heap used at the end of the most recent garbage collection, bytes (each heap pool
     *         as the latest collection that reports it left it; see the class comment), 0 before the
     *         first, or -1 if the JVM does not tell
     */
    public static long heapAfterLastGc() {
        Set<String> heapPools = new HashSet<>();
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                heapPools.add(pool.getName());
            }
        }
        Map<String, Long> endTime = new HashMap<>();
        Map<String, Long> used = new HashMap<>();
        boolean told = false;
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            if (!(gc instanceof com.sun.management.GarbageCollectorMXBean sun)) {
                continue;
            }
            told = true;
            com.sun.management.GcInfo info = sun.getLastGcInfo();
            if (info == null) {
                continue;
            }
            for (Map.Entry<String, MemoryUsage> pool : info.getMemoryUsageAfterGc().entrySet()) {
                if (heapPools.contains(pool.getKey()) && info.getEndTime() >= endTime.getOrDefault(pool.getKey(), -1L)) {
                    endTime.put(pool.getKey(), info.getEndTime());
                    used.put(pool.getKey(), pool.getValue().getUsed());
                }
            }
        }
        return told ? used.values().stream().mapToLong(Long::longValue).sum() : -1;
    }

    /** @return garbage collections so far, all collectors */
    public static long collections() {
        long n = 0;
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            n += Math.max(0, gc.getCollectionCount());
        }
        return n;
    }

    /**
     * This JVM's figures at the end of a run, in this order: {@code rss_mb} and {@code hwm_mb} (its
     * resident set now and at its largest), {@code heap_gc_mb} (heap used after the last collection),
     * {@code heap_committed_mb}, {@code gcs} (collections so far), then, after one full collection
     * ({@link System#gc()}) that this forces, {@code heap_live_mb} (heap used after it), and
     * {@code heap_samples} if there are samples. What this machine does not give reads
     * {@code unavailable}.
     *
     * @param samples the heap samples taken during the run, or {@code null}
     * @return the figures
     */
    public static Map<String, String> figures(Sampler samples) {
        Map<String, String> f = new LinkedHashMap<>();
        Optional<Resident> resident = resident(Path.of("/proc/self/status"));
        f.put("rss_mb", resident.map(r -> mb(r.rssKb() * 1024)).orElse(UNAVAILABLE));
        f.put("hwm_mb", resident.map(r -> mb(r.hwmKb() * 1024)).orElse(UNAVAILABLE));
        long afterGc = heapAfterLastGc();
        f.put("heap_gc_mb", afterGc < 0 ? UNAVAILABLE : mb(afterGc));
        f.put("heap_committed_mb", mb(ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getCommitted()));
        f.put("gcs", Long.toString(collections()));
        System.gc();
        f.put("heap_live_mb", mb(ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed()));
        if (samples != null) {
            f.put("heap_samples", samples.samples());
        }
        return f;
    }

    /**
     * @param bytes bytes
     * @return them in MiB with one decimal
     */
    static String mb(long bytes) {
        return String.format(Locale.ROOT, "%.1f", bytes / MIB);
    }

    /**
     * @param figures figures
     * @return them as {@code key=value} fields separated by spaces
     */
    static String fields(Map<String, String> figures) {
        StringJoiner j = new StringJoiner(" ");
        figures.forEach((k, v) -> j.add(k + "=" + v));
        return j.toString();
    }

    /**
     * @param figures figures
     * @return the line a client JVM prints them on: {@value #CLIENT_MARK} and the fields
     */
    static String clientLine(Map<String, String> figures) {
        return CLIENT_MARK + " " + fields(figures);
    }

    /**
     * Finds a client JVM's figures in its log.
     *
     * @param lines the log's lines
     * @return the figures on its last {@value #CLIENT_MARK} line, or empty if it has none
     */
    static Optional<Map<String, String>> clientFigures(List<String> lines) {
        for (int i = lines.size() - 1; i >= 0; i--) {
            String line = lines.get(i).strip();
            if (line.startsWith(CLIENT_MARK + " ")) {
                Map<String, String> f = new LinkedHashMap<>();
                for (String field : line.substring(CLIENT_MARK.length()).strip().split("\\s+")) {
                    int eq = field.indexOf('=');
                    if (eq > 0) {
                        f.put(field.substring(0, eq), field.substring(eq + 1));
                    }
                }
                return Optional.of(f);
            }
        }
        return Optional.empty();
    }

    /**
     * Samples the heap after the last garbage collection every {@code every} steps, forcing none:
     * {@code step:MiB} (two decimals, so a growth of tens of KiB shows) for the first step seen at or
     * past each multiple of {@code every}. Cheap when no sample is due; one thread at a time.
     */
    public static final class Sampler {
        private final long every;
        private final LongSupplier heap;
        private final StringJoiner samples = new StringJoiner(",");
        private long next;
        private long last = -1;

        /**
         * @param every steps between samples, at least 1
         */
        public Sampler(long every) {
            this(every, JvmMemory::heapAfterLastGc);
        }

        /**
         * @param every steps between samples, at least 1
         * @param heap  the heap after the last collection, bytes
         */
        Sampler(long every, LongSupplier heap) {
            if (every < 1) {
                throw new IllegalArgumentException(every + " was supplied for steps between heap samples: it must be at least 1");
            }
            this.every = every;
            this.heap = heap;
            this.next = every;
        }

        /**
         * Takes a sample if one is due.
         *
         * @param step the step the run has reached
         */
        public synchronized void at(long step) {
            if (step >= next) {
                add(step);
                next = (step / every + 1) * every;
            }
        }

        /**
         * Takes a sample whether or not one is due, such as at the end of the run, unless one was
         * taken at this step.
         *
         * @param step the step the run has reached
         */
        public synchronized void add(long step) {
            if (step == last) {
                return;
            }
            last = step;
            long bytes = heap.getAsLong();
            samples.add(step + ":" + (bytes < 0 ? UNAVAILABLE : String.format(Locale.ROOT, "%.2f", bytes / MIB)));
        }

        /** @return the samples, {@code step:MiB} separated by commas; empty if none */
        public synchronized String samples() {
            return samples.toString();
        }
    }
}
