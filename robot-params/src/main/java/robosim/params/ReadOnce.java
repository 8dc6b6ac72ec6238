package robosim.params;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;

/**
 * What was read from a file, kept while the file does not change: a team of robots built from one
 * parameter file reads and parses it once, not once per robot (and logs its warnings once). A file
 * whose size or modification time changes is read again. Holds at most {@link #MAX_FILES} files.
 *
 * @param <T> what is read; immutable, since every caller shares it
 */
final class ReadOnce<T> {
    /** The most files kept; past it the memory starts afresh. */
    static final int MAX_FILES = 64;

    private record Version(Path file, long modifiedNanos, long size) {
    }

    private final Map<Version, T> read = new ConcurrentHashMap<>();
    private final Function<Path, T> reader;

    /** @param reader reads a file; it throws as the file's reader does */
    ReadOnce(Function<Path, T> reader) {
        this.reader = reader;
    }

    /**
     * @param file the file
     * @return what its reader gives, read again only if the file changed since
     */
    T get(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(absolute, BasicFileAttributes.class);
        } catch (IOException e) {
            return reader.apply(file); // the reader says why it cannot be read
        }
        Version v = new Version(absolute, a.lastModifiedTime().to(java.util.concurrent.TimeUnit.NANOSECONDS), a.size());
        T known = read.get(v);
        if (known != null) {
            return known;
        }
        T fresh = reader.apply(file);
        if (read.size() >= MAX_FILES) {
            read.clear();
        }
        read.put(v, fresh);
        return fresh;
    }
}
