package robosim.params;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.nio.file.Files;
import java.nio.file.Path;

/** Where the shipped robot parameter files are, for tests. */
final class ShippedRobots {
    private ShippedRobots() {
    }

    /** @return {@code testLoadFiles/robots} under the project root */
    static Path dir() {
        return projectRoot().resolve("testLoadFiles").resolve("robots");
    }

    /** Surefire names the project root in robosim.root; elsewhere, walk up to the testLoadFiles dir. */
    static Path projectRoot() {
        String property = System.getProperty("robosim.root");
        if (property != null && Files.isDirectory(Path.of(property, "testLoadFiles"))) {
            return Path.of(property);
        }
        Path dir = Path.of("").toAbsolutePath();
        while (dir != null && !Files.isDirectory(dir.resolve("testLoadFiles"))) {
            dir = dir.getParent();
        }
        assertNotNull(dir, "no directory holding testLoadFiles above " + Path.of("").toAbsolutePath());
        return dir;
    }
}
