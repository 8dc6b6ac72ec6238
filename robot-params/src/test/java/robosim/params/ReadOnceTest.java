package robosim.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ReadOnceTest {
    @TempDir
    Path dir;

    @Test
    void aFileIsReadOnceWhileItDoesNotChange() throws Exception {
        Path file = Files.writeString(dir.resolve("a.p"), "RobotRadius 250\n");
        AtomicInteger reads = new AtomicInteger();
        ReadOnce<String> once = new ReadOnce<>(p -> reads.incrementAndGet() + ":" + p.getFileName());
        String first = once.get(file);
        assertSame(first, once.get(file));
        assertSame(first, once.get(dir.resolve("x/../a.p")));
        assertEquals(1, reads.get());
    }

    @Test
    void aChangedFileIsReadAgain() throws Exception {
        Path file = Files.writeString(dir.resolve("a.p"), "RobotRadius 250\n");
        AtomicInteger reads = new AtomicInteger();
        ReadOnce<Integer> once = new ReadOnce<>(p -> reads.incrementAndGet());
        assertEquals(1, once.get(file));
        Files.writeString(file, "RobotRadius 300 ; longer now\n");
        assertEquals(2, once.get(file));
    }

    @Test
    void aTeamFromOneParameterFileSharesItsParameters() {
        assertSame(RobotParameterFiles.load("p3dx"), RobotParameterFiles.load("p3dx"));
    }
}
