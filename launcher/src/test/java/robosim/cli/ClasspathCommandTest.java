package robosim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code robosim classpath}: the jars under the RoboSim root, absolute, in one line. */
class ClasspathCommandTest {
    @TempDir
    Path root;

    @Test
    void printsEveryJarOfTheLibFolderAbsoluteAndSortedOnOneLine() throws Exception {
        Path lib = Files.createDirectories(root.resolve("launcher/target/lib"));
        Files.writeString(lib.resolve("picocli-4.7.5.jar"), "");
        Files.writeString(lib.resolve("aria-api-0.1.0-SNAPSHOT.jar"), "");
        Files.writeString(lib.resolve("notes.txt"), "");
        Files.createDirectories(lib.resolve("folder.jar"));
        Run r = atRoot(root, () -> Run.execute("classpath"));
        assertEquals(0, r.exit(), r.err());
        String abs = lib.toAbsolutePath().normalize().toString();
        assertEquals(abs + File.separator + "aria-api-0.1.0-SNAPSHOT.jar" + File.pathSeparator
                + abs + File.separator + "picocli-4.7.5.jar" + System.lineSeparator(), r.out());
        assertEquals("", r.err());
    }

    @Test
    void aRootGivenRelativeStillGivesAbsolutePaths() throws Exception {
        Path lib = Files.createDirectories(root.resolve("launcher/target/lib"));
        Files.writeString(lib.resolve("a.jar"), "");
        Path relative = Path.of("").toAbsolutePath().relativize(root.toAbsolutePath());
        Run r = atRoot(relative, () -> Run.execute("classpath"));
        assertEquals(0, r.exit(), r.err());
        assertTrue(Path.of(r.out().strip()).isAbsolute(), r.out());
        assertEquals(lib.resolve("a.jar").toAbsolutePath().normalize(), Path.of(r.out().strip()));
    }

    @Test
    void withoutBuiltJarsItSaysWhereItLookedAndExitsWith1() {
        Run r = atRoot(root, () -> Run.execute("classpath"));
        assertEquals(1, r.exit());
        assertEquals("", r.out());
        assertEquals("robosim classpath: no RoboSim jars in " + root.resolve("launcher/target/lib").toAbsolutePath()
                + ": bin/robosim builds them on first use (or run mvn -B package -DskipTests in the clone)", r.firstLine());
    }

    @Test
    void anArgumentIsABadCommandLine() {
        Run r = Run.execute("classpath", "extra");
        assertEquals(2, r.exit());
        r.assertHintToHelp("robosim classpath");
    }

    private static Run atRoot(Path root, Supplier<Run> run) {
        String old = System.setProperty("robosim.root", root.toString());
        try {
            return run.get();
        } finally {
            if (old == null) {
                System.clearProperty("robosim.root");
            } else {
                System.setProperty("robosim.root", old);
            }
        }
    }
}
