package robosim.env.world.xml;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import robosim.env.world.World;

/** Writes world files into a test's temporary directory, beside a copy of the robot parameter files. */
final class WorldFixtures {
    private final Path dir;

    /**
     * @param dir the test's temporary directory; the robot parameter files are copied to
     *            {@code dir/robots} so that worlds can name {@code ../robots/p3dx.p} as the shipped ones do
     */
    WorldFixtures(Path dir) {
        this.dir = dir;
        try {
            Files.createDirectories(dir.resolve("robots"));
            Files.createDirectories(dir.resolve("environment"));
            for (String p : new String[] {"p3dx.p", "p3at.p"}) {
                Files.copy(root().resolve("testLoadFiles/robots").resolve(p), dir.resolve("robots").resolve(p));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** @return the project's root directory */
    static Path root() {
        String property = System.getProperty("robosim.root");
        Path start = Path.of(property != null ? property : "").toAbsolutePath();
        for (Path p = start; p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("testLoadFiles"))) {
                return p;
            }
        }
        throw new IllegalStateException("no testLoadFiles directory above " + start);
    }

    /** @return the file written, {@code dir/environment/name} */
    Path write(String name, String text) {
        Path file = dir.resolve("environment").resolve(name);
        try {
            Files.writeString(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return file;
    }

    /** @return the parameter file written, {@code dir/robots/name} */
    Path writeRobot(String name, String text) {
        Path file = dir.resolve("robots").resolve(name);
        try {
            Files.writeString(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return file;
    }

    /** Reads a world written as {@code name}. */
    World read(String name, String text) {
        return WorldReader.read(write(name, text));
    }

    /**
     * Asserts that reading the world fails at {@code line} with a message naming the file and
     * containing each of {@code words}.
     *
     * @return the exception, for further checks
     */
    WorldFileException fails(String name, String text, int line, String... words) {
        Path file = write(name, text);
        WorldFileException e = assertThrows(WorldFileException.class, () -> WorldReader.read(file));
        String message = e.getMessage();
        assertTrue(message.contains(name + ":" + line + ": "), () -> "expected " + name + ":" + line + " in: " + message);
        assertTrue(e.line() == line, () -> "line " + e.line() + " in: " + message);
        for (String w : words) {
            assertTrue(message.contains(w), () -> "expected '" + w + "' in: " + message);
        }
        return e;
    }
}
